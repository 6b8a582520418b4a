// The energy of a World's moving bodies, for the tests that bound what a run may gain.
#pragma once

#include "contact/world.h"
#include "kinematics/momentum.h"

namespace lamina {

// E = Σ (½ m vᵀv + ½ ωᵀ I ω) − m g·x over the dynamic bodies, in J: eq. 1-47 plus gravity's
// potential energy, 0 at x = 0 (the text's E is kinetic only).
inline double mechanical_energy(const World& world) {
  const Vec3& g = world.settings().step.gravity;
  double energy = 0.0;
  for (const RigidBody& b : world.bodies()) {
    if (b.is_static()) continue;
    energy += kinetic_energy(b.mass, b.v, b.inertia_world(), b.angular_velocity) -
              b.mass * g.dot(b.x);
  }
  return energy;
}

// Σ m |g| h: the energy of lifting every dynamic body by `height`, in J. The energy bounds are
// stated in it.
inline double lift_energy(const World& world, double height) {
  double weight = 0.0;  // in N
  for (const RigidBody& b : world.bodies()) {
    if (!b.is_static()) weight += b.mass * world.settings().step.gravity.norm();
  }
  return weight * height;
}

}  // namespace lamina
