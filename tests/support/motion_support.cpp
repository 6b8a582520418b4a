#include "support/motion_support.h"

#include "kinematics/inertia.h"
#include "kinematics/momentum.h"

namespace lamina::testing {

RigidBody box_3d(const Vec3& x, const Quat& q) {
  const double m = 2.0;
  return RigidBody::dynamic_body(m, box_inertia(m, 0.5, 0.2), x, q);
}

double kinetic_energy_of(const RigidBody& b) {
  return kinetic_energy(b.mass, b.v, b.inertia_world(), b.angular_velocity);
}

double angle_increment(const Quat& q0, const Quat& q1) { return planar_angle(q1 * q0.conjugate()); }

}  // namespace lamina::testing
