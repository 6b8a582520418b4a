// Quaternions as the text uses them: orientation, rotation of vectors, and their time derivative.
//
// Eigen's Quaterniond already implements the product (eq. 1-18), the conjugate and the matrix
// (eq. 1-22); Lamina uses it and keeps the text's formulas here, written out, so that tests can
// show the two agree and a student can read each equation as code.
#pragma once

#include "kinematics/math_types.h"

namespace lamina {

// eq. 1-17, 1-18: (w0 + v0)(w1 + v1) = (w0 w1 − v0·v1) + w0 v1 + w1 v0 + v0 × v1.
Quat quaternion_product(const Quat& a, const Quat& b);

// The conjugate q* = w − v; for a unit q it is the inverse rotation.
Quat quaternion_conjugate(const Quat& q);

// eq. 1-19: q = cos(θ/2) + d sin(θ/2), a rotation by θ about the unit axis d.
Quat quaternion_from_axis_angle(const Vec3& unit_axis, double angle);

// eq. 1-22: the rotation matrix of a unit quaternion.
Mat3 quaternion_to_matrix(const Quat& q);

// eq. 1-20: q v q* with v as a pure quaternion; equals R v for a unit q.
Vec3 quaternion_rotate(const Quat& q, const Vec3& v);

// eq. 1-29: q̇ = ½ ω̂ q, with ω̂ = (0, ω) the pure quaternion of the angular velocity.
Quat quaternion_derivative(const Vec3& angular_velocity, const Quat& q);

// The pure quaternion (0, v).
inline Quat pure_quaternion(const Vec3& v) { return Quat(0.0, v.x(), v.y(), v.z()); }

}  // namespace lamina
