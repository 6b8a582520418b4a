// Mass distribution: centre of mass and inertia tensors (chapter 1, "Inertia tensor").
//
// Planar convention: Lamina's box and disc are 3D solids one metre deep along z (a cuboid and
// a cylinder), so a shape's mass is density × area, as in Box2D, and I_zz equals Box2D's
// rotational inertia. I_xx and I_yy are the solid's own; planar motion never uses them.
#pragma once

#include <vector>

#include "kinematics/math_types.h"

namespace lamina {

// One point mass of a point set.
struct PointMass {
  double mass;     // m_i, in kg
  Vec3 position;   // x_i, in m
};

// Depth along z of Lamina's planar solids, in m.
inline constexpr double planar_depth = 1.0;

// eq. 1-1: x = Σ m_i x_i / m.
Vec3 centre_of_mass(const std::vector<PointMass>& points);

// eq. 1-34..1-36: I = Σ m_i (r_iᵀ r_i E − r_i r_iᵀ) = Σ −m_i Skew(r_i)², r_i = x_i − centre.
Mat3 point_set_inertia(const std::vector<PointMass>& points, const Vec3& centre);

// Body-frame inertia I0 of a solid cuboid with half extents (hx, hy) and depth planar_depth.
Mat3 box_inertia(double mass, double half_x, double half_y);

// Body-frame inertia I0 of a solid cylinder of radius r and length planar_depth along z.
Mat3 disc_inertia(double mass, double radius);

// eq. 1-37: I(t) = R(t) I(0) R(t)ᵀ (also used for the inverse, R I0⁻¹ Rᵀ).
Mat3 world_inertia(const Mat3& rotation, const Mat3& body_inertia);

}  // namespace lamina
