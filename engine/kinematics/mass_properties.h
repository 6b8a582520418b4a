// Mass properties of the plane shapes beyond the box and the disc: a convex polygon and a
// capsule (chapter 1, "Inertia tensor"; the text sends its readers to a note on polyhedral mass
// properties, of which this is the planar case).
//
// A shape is a region S of the x–y plane, extruded planar_depth along z (inertia.h). Per unit
// density and depth its moments are
//   A = ∫_S dA                      area, in m²
//   c = (1/A) ∫_S r dA              centroid, in m (the body's centre of mass)
//   J = ∫_S (r − c)(r − c)ᵀ dA      second moment about the centroid, in m⁴
// A polygon with vertices v_0 … v_{n−1} (counter-clockwise) is a fan of triangles (o, v_i, v_i+1)
// from a point o inside it (its first vertex); each triangle adds, with a_i = ½ (v_i − o) × (v_i+1 − o)
// and p = v_i − o, q = v_i+1 − o:
//   A   += a_i
//   ∫ r  += a_i (p + q)/3
//   ∫ x² += a_i (p_x² + p_x q_x + q_x²)/6
//   ∫ y² += a_i (p_y² + p_y q_y + q_y²)/6
//   ∫ xy += a_i (2 p_x p_y + p_x q_y + q_x p_y + 2 q_x q_y)/12
// and J moves from o to c by the parallel axis theorem, J = ∫ r rᵀ − A c cᵀ (r from o).
// The prism's inertia about its centroid (eq. 1-34 integrated over the solid) is
//   I0 = m/A [ J_yy + A L²/12   −J_xy            0
//              −J_xy            J_xx + A L²/12   0
//              0                0                J_xx + J_yy ]
// with L = planar_depth: I_zz, the only entry planar motion uses, is m (J_xx + J_yy)/A.
#pragma once

#include <vector>

#include "kinematics/math_types.h"

namespace lamina {

struct AreaMoments {
  double area = 0.0;                 // A, in m²
  Vec2 centroid = Vec2::Zero();      // c, in m, in the frame the shape was given in
  Mat2 second = Mat2::Zero();        // J about the centroid, in m⁴
};

// The moments of a convex polygon, vertices counter-clockwise, by the triangle fan above.
AreaMoments polygon_moments(const std::vector<Vec2>& vertices);

// The moments of a capsule: the points within `radius` of the segment from (−length/2, 0) to
// (length/2, 0), a rectangle 2ρ × l with a half disc at each end. Centroid at the origin.
//   A = 2ρ l + π ρ²
//   J_xx = ρ l³/6 + π ρ² l²/4 + 4 ρ³ l/3 + π ρ⁴/4   (rectangle; each half disc about its flat
//                                                 side's centre, moved out by l/2)
//   J_yy = 2 ρ³ l/3 + π ρ⁴/4
AreaMoments capsule_moments(double radius, double length);

// The body-frame inertia I0 of a shape extruded planar_depth along z, of mass m, about its
// centroid (the formula above).
Mat3 prism_inertia(double mass, const AreaMoments& moments);

}  // namespace lamina
