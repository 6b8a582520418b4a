// `islands`: Lamina's own method (beyond the text), the default of `lamina run` and of scene
// files without a "solver". Each island (islands.h) is solved the way that holds it:
//
//   contacts only, small   exactly (exact_mlcp.h): no sweep count to run out of, so a box on one
//                          a thousand times lighter, or a stack of twenty, gets the λ that stops
//                          it, not the λ that PGS had reached after ten sweeps.
//   with joints, small     exactly, in joint_substeps substeps of Δt / joint_substeps, the
//                          joints' rows written again from the bodies' poses before each. A
//                          velocity solve, however exact, holds J V = ζ only to first order: a
//                          link turning by ω Δt opens its joints by about r (ω Δt)² / 2, and a
//                          light link between a heavy ball and a pin turns fast; eight substeps
//                          cut that error 64-fold per substep (Box2D v3 substeps for the same
//                          reason).
//   large                  by PGS, `pgs`'s sweeps: a pyramid of 20 is 1100 rows, where PGS is
//                          cheap and holds (chapter 6's table).
//
// The rest of the step is `pgs`'s: split impulse with its 5 mm slop (the push-out moves the bodies
// of every island once, after their solve), restitution, the contact cache and its warm start
// (a substepped island keeps the mean of its substeps' λ).
#pragma once

#include <memory>

#include "contact/step_method.h"

namespace lamina {

// The substeps of a small island with joints.
constexpr int joint_substeps = 8;

std::unique_ptr<StepMethod> make_island_method();

}  // namespace lamina
