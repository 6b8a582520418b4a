// Force and torque about the centre of mass from forces applied at world points.
#pragma once

#include "kinematics/math_types.h"

namespace lamina {

// The total force F and torque τ on a body about its centre of mass x.
struct Wrench {
  Vec3 force = Vec3::Zero();   // F = Σ F_i, in N (eq. 1-31)
  Vec3 torque = Vec3::Zero();  // τ = Σ (x_i − x) × F_i, in N·m (eq. 1-33)

  // Adds the force F_i applied at world point x_i to a body whose centre of mass is x.
  void add_at_point(const Vec3& force_i, const Vec3& point, const Vec3& x);
};

}  // namespace lamina
