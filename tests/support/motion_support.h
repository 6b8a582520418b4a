// What the chapter-2 tests share: gravity, a 3D box, a body's kinetic energy and a planar
// body's turn in one step.
#pragma once

#include "kinematics/math_types.h"
#include "motion/rigid_body.h"

namespace lamina::testing {

inline const Vec3 gravity(0.0, -9.8, 0.0);  // the project's planar gravity (y up, as Box2D)

// A dynamic 3D box (half extents 0.5, 0.2 and depth 1 m) at x with orientation q.
RigidBody box_3d(const Vec3& x, const Quat& q);

// E of eq. 1-47 for one body, in J.
double kinetic_energy_of(const RigidBody& b);

// Rotation angle of q1 relative to q0 about z, in (−π, π]: one step's increment, summed to
// follow a planar body's angle through any number of turns.
double angle_increment(const Quat& q0, const Quat& q1);

}  // namespace lamina::testing
