#include "kinematics/particle.h"

namespace lamina {

Vec3 particle_position(const Vec3& x, const Mat3& rotation, const Vec3& body_offset) {
  // eq. 1-25
  return x + rotation * body_offset;
}

Vec3 particle_velocity(const Vec3& v, const Vec3& angular_velocity, const Vec3& x,
                       const Vec3& particle) {
  // eq. 1-30
  return v + angular_velocity.cross(particle - x);
}

Vec3 particle_acceleration(const Vec3& linear_acceleration, const Vec3& angular_acceleration,
                           const Vec3& angular_velocity, const Vec3& r) {
  // eq. 1-49
  return linear_acceleration + angular_acceleration.cross(r) +
         angular_velocity.cross(angular_velocity.cross(r));
}

}  // namespace lamina
