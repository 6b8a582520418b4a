#include "kinematics/momentum.h"

#include <Eigen/Cholesky>

namespace lamina {

Vec3 linear_momentum(double mass, const Vec3& v) {
  // eq. 1-38
  return mass * v;
}

Vec3 angular_momentum(const Mat3& world_inertia, const Vec3& angular_velocity) {
  // eq. 1-41
  return world_inertia * angular_velocity;
}

Vec3 angular_acceleration(const Mat3& world_inertia, const Vec3& angular_velocity,
                          const Vec3& torque) {
  const Vec3 l = angular_momentum(world_inertia, angular_velocity);
  // eq. 1-46: ω̇ = I⁻¹ (L × ω + L̇), with L̇ = τ (eq. 1-43)
  return world_inertia.ldlt().solve(l.cross(angular_velocity) + torque);
}

double kinetic_energy(double mass, const Vec3& v, const Mat3& world_inertia,
                      const Vec3& angular_velocity) {
  // eq. 1-47
  return 0.5 * mass * v.dot(v) + 0.5 * angular_velocity.dot(world_inertia * angular_velocity);
}

double power(const Vec3& force, const Vec3& v, const Vec3& torque, const Vec3& angular_velocity) {
  // eq. 1-48
  return force.dot(v) + torque.dot(angular_velocity);
}

}  // namespace lamina
