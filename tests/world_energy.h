// The energy bounds of the tests that bound what a run may gain (mechanical_energy, the energy
// itself, is the engine's: contact/world.h).
#pragma once

#include "contact/world.h"

namespace lamina {

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
