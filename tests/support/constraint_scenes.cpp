#include "support/constraint_scenes.h"

#include <cmath>
#include <memory>
#include <random>

#include "constraints/angle_limit.h"
#include "constraints/distance_constraint.h"
#include "constraints/incline_constraint.h"
#include "constraints/jacobian_rows.h"
#include "constraints/revolute_joint.h"

namespace lamina {

double relative_error(double value, double expected) {
  return std::abs(value - expected) / std::abs(expected);
}

ConstraintList pinned_rod(std::vector<RigidBody>& bodies, double angle) {
  bodies.push_back(box_body(10.0, 0.5, 0.025, 0.5 * Vec3(std::cos(angle), std::sin(angle), 0.0), angle));
  ConstraintList constraints;
  constraints.push_back(std::make_unique<RevoluteJoint>(anchor_at(bodies, world, Vec3::Zero()),
                                                        anchor_at(bodies, 0, Vec3::Zero())));
  return constraints;
}

ConstraintList mixed_scene(std::vector<RigidBody>& bodies) {
  for (int k = 0; k < 3; ++k) bodies.push_back(box_body(5.0, 0.3, 0.1, Vec3(0.6 * k + 0.3, 0.0, 0.0), 0.1 * k));
  bodies.push_back(box_body(2.0, 0.2, 0.2, Vec3(3.0, 1.0, 0.0), 0.4));
  bodies.push_back(RigidBody::static_body(Vec3(5.0, 0.0, 0.0), planar_orientation(0.3)));
  bodies.push_back(box_body(2.0, 0.4, 0.1, Vec3(5.5, -0.2, 0.0), -0.2));
  ConstraintList c;
  for (int k = 0; k < 3; ++k) {
    const Vec3 pivot(0.6 * k, 0.0, 0.0);
    c.push_back(std::make_unique<RevoluteJoint>(anchor_at(bodies, k == 0 ? world : k - 1, pivot),
                                                anchor_at(bodies, k, pivot)));
  }
  c.push_back(std::make_unique<DistanceConstraint>(Anchor{world, Vec3(2.0, 1.0, 0.0)},
                                                   Anchor{2, Vec3(0.3, 0.1, 0.0)}, 1.2));
  c.push_back(std::make_unique<AngleLimit>(0, 1, -0.05, LimitSide::lower));
  c.push_back(std::make_unique<InclineConstraint>(3, Vec3(3.0, 0.9, 0.0), Vec3(0.6, 0.8, 0.0)));
  c.push_back(std::make_unique<RevoluteJoint>(anchor_at(bodies, 4, Vec3(5.2, -0.1, 0.0)),
                                              anchor_at(bodies, 5, Vec3(5.2, -0.1, 0.0))));
  return c;
}

ConstraintList shaken_mixed_scene(std::vector<RigidBody>& bodies, unsigned seed) {
  ConstraintList constraints = mixed_scene(bodies);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (RigidBody& b : bodies) {
    if (b.is_static()) continue;
    b.v = Vec3(u(rng), u(rng), u(rng));
    b.angular_velocity = Vec3(u(rng), u(rng), u(rng));
    b.force = 10.0 * Vec3(u(rng), u(rng), u(rng));
    b.torque = Vec3(u(rng), u(rng), u(rng));
  }
  return constraints;
}

}  // namespace lamina
