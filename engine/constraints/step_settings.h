// The numbers every step is made with, in one place: g, Δt, β, the PGS sweeps, and the pitfalls
// put back on purpose (none by default). The chapter-3 step (constrained_step.h), the World
// (contact/world.h) and scene files (scene/scene.h) all hold this one type, so each default is
// written once.
#pragma once

#include "kinematics/math_types.h"
#include "motion/pitfalls.h"

namespace lamina {

struct StepSettings {
  Vec3 gravity = Vec3(0.0, -9.8, 0.0);  // g, in m/s²; y is up (the text's chapter 5 has z up)
  double dt = 1.0 / 60.0;               // Δt, in s
  double beta = 0.2;                    // β: fraction of a position error removed per step (eq. 3-14, 4-4)
  int iterations = 10;                  // PGS sweeps per step, MAX_ITERATION of the text; 0 keeps λ_exp
  Pitfalls pitfalls;                    // classic mistakes put back (motion/pitfalls.h); none
};

// Throws std::invalid_argument naming the first setting out of range: g finite and in the
// plane, Δt finite and > 0, 0 ≤ β ≤ 1, sweeps ≥ 0.
void validate(const StepSettings& settings);

}  // namespace lamina
