#include "kinematics/quaternion.h"

#include <cmath>

namespace lamina {

Quat quaternion_product(const Quat& a, const Quat& b) {
  const Vec3 v0 = a.vec();
  const Vec3 v1 = b.vec();
  // eq. 1-18
  const double w = a.w() * b.w() - v0.dot(v1);
  const Vec3 v = a.w() * v1 + b.w() * v0 + v0.cross(v1);
  return Quat(w, v.x(), v.y(), v.z());
}

Quat quaternion_conjugate(const Quat& q) { return Quat(q.w(), -q.x(), -q.y(), -q.z()); }

Quat quaternion_from_axis_angle(const Vec3& unit_axis, double angle) {
  // eq. 1-19
  const Vec3 v = std::sin(0.5 * angle) * unit_axis;
  return Quat(std::cos(0.5 * angle), v.x(), v.y(), v.z());
}

Mat3 quaternion_to_matrix(const Quat& q) {
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  Mat3 r;
  // eq. 1-22
  r << 1 - 2 * y * y - 2 * z * z, 2 * x * y - 2 * w * z, 2 * x * z + 2 * w * y,
       2 * x * y + 2 * w * z, 1 - 2 * x * x - 2 * z * z, 2 * y * z - 2 * w * x,
       2 * x * z - 2 * w * y, 2 * y * z + 2 * w * x, 1 - 2 * x * x - 2 * y * y;
  return r;
}

Vec3 quaternion_rotate(const Quat& q, const Vec3& v) {
  // eq. 1-20: q v q*
  return quaternion_product(quaternion_product(q, pure_quaternion(v)), quaternion_conjugate(q)).vec();
}

Quat quaternion_derivative(const Vec3& angular_velocity, const Quat& q) {
  // eq. 1-29: q̇ = ½ ω̂ q
  const Quat wq = quaternion_product(pure_quaternion(angular_velocity), q);
  return Quat(0.5 * wq.w(), 0.5 * wq.x(), 0.5 * wq.y(), 0.5 * wq.z());
}

}  // namespace lamina
