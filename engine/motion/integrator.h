// One step of unconstrained motion, t → t + Δt (chapter 2, eq. 2-1..2-8).
#pragma once

#include <vector>

#include "motion/pitfalls.h"
#include "motion/rigid_body.h"

namespace lamina {

// Which velocity moves the position.
enum class Integration {
  semi_implicit,  // the text's eq. 2-5: x(t+Δt) = x + v(t+Δt) Δt (symplectic Euler)
  explicit_euler  // the explicit variant: x(t+Δt) = x + v(t) Δt, q from ω(t)
};

// Advances one body by Δt under its accumulated force and torque (eq. 2-1..2-8).
// The accumulators are left as they are; the caller clears them. Of the pitfalls (pitfalls.h),
// no-renormalisation is read here.
void integrate(RigidBody& body, double dt, Integration scheme = Integration::semi_implicit,
               Pitfalls pitfalls = {});

// Adds gravity m g to a dynamic body's force (F_ext of eq. 5-2; a static body gets none), or to
// every body's.
void apply_gravity(RigidBody& body, const Vec3& gravity);
void apply_gravity(std::vector<RigidBody>& bodies, const Vec3& gravity);

// The chapter-2 world step: gravity, integrate each body, clear the forces.
void step_unconstrained(std::vector<RigidBody>& bodies, const Vec3& gravity, double dt,
                        Integration scheme = Integration::semi_implicit);

}  // namespace lamina
