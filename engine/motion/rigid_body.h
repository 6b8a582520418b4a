// A rigid body with the 3D state of chapter 2: x, q, v, ω, and what is derived from them.
#pragma once

#include "kinematics/mass_properties.h"
#include "kinematics/math_types.h"

namespace lamina {

struct RigidBody {
  // The fields most read lie first: q, x and m⁻¹ in the first 64 bytes, v, ω and m in the next
  // 56, so that the contact rows, which read x and m⁻¹, then v and ω, of bodies all over the
  // list, touch fewer cache lines (a step at base 80 about 2 % faster, the same numbers).
  Quat q = Quat::Identity();                  // orientation, a unit quaternion
  Vec3 x = Vec3::Zero();                      // centre of mass, world frame, in m
  // A static body is the text's fixed body of infinite mass (eq. 5-1): what the step uses of it
  // is m⁻¹ = 0 and I⁻¹ = 0; its m and I0 are +∞ (diagonal), to be read, never multiplied.
  double inverse_mass = 0.0;                  // m⁻¹, in 1/kg; 0 for a static body (eq. 5-1)
  Vec3 v = Vec3::Zero();                      // linear velocity, in m/s
  Vec3 angular_velocity = Vec3::Zero();       // ω, world frame, in rad/s
  double mass = 0.0;                          // m, in kg; +∞ for a static body

  Mat3 rotation = Mat3::Identity();           // R, from q by eq. 1-22 (eq. 2-7)
  Mat3 inverse_inertia_world = Mat3::Zero();  // I⁻¹ = R I0⁻¹ Rᵀ (eq. 2-8, 1-37)

  Vec3 force = Vec3::Zero();                  // F accumulated this step, in N (eq. 1-31)
  Vec3 torque = Vec3::Zero();                 // τ about x accumulated this step, in N·m (eq. 1-33)

  Mat3 inertia_body = Mat3::Zero();           // I0, body-frame inertia tensor, in kg·m²; +∞ E static
  Mat3 inverse_inertia_body = Mat3::Zero();   // I0⁻¹; zero for a static body (eq. 5-1)

  // A body that moves, with mass m > 0 and a symmetric positive definite I0.
  // Throws std::invalid_argument for a non-finite or non-positive mass, a bad I0, a non-finite
  // position or an orientation that is not a unit quaternion.
  static RigidBody dynamic_body(double mass, const Mat3& inertia_body, const Vec3& x,
                                const Quat& q = Quat::Identity());
  // A body that never moves: zero inverse mass and inertia (eq. 5-1), so no force moves it.
  static RigidBody static_body(const Vec3& x, const Quat& q = Quat::Identity());

  // Adds force F applied at world point p: F to the force, (p − x) × F to the torque (eq. 1-33).
  void apply_force_at(const Vec3& f, const Vec3& p);
  // Clears the accumulated force and torque, as at the start of every step.
  void clear_forces();
  // Recomputes R (eq. 2-7) and I⁻¹ (eq. 2-8) from q.
  void update_derived();

  // I = R I0 Rᵀ (eq. 1-37); +∞ E for a static body.
  Mat3 inertia_world() const;
  bool is_static() const { return inverse_mass == 0.0; }
  // True while x, q, v and ω are all finite numbers: a step that breaks this has diverged.
  bool has_finite_state() const;
};

// The planar orientation of angle θ about z (eq. 1-19 with d = z).
Quat planar_orientation(double angle);
// The angle θ about z of a planar orientation, in (−π, π].
double planar_angle(const Quat& q);

// A dynamic box of the given density, half extents (hx, hy) and depth 1 m (see inertia.h).
RigidBody box_body(double density, double half_x, double half_y, const Vec3& x, double angle = 0.0);
// A dynamic disc of the given density, radius and depth 1 m.
RigidBody disc_body(double density, double radius, const Vec3& x, double angle = 0.0);
// A dynamic prism (a polygon or a capsule 1 m deep) of the given density and area moments about
// its centroid (mass_properties.h); x is its centre of mass.
RigidBody prism_body(double density, const AreaMoments& moments, const Vec3& x, double angle = 0.0);

}  // namespace lamina
