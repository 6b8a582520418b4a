// `exact`: the step's MLCP solved exactly, island by island (beyond the text).
//
// The text solves eq. 3-24 by Projected Gauss-Seidel only, which stops after MAX_ITERATION sweeps
// wherever it has got to; its reference [3] (Baraff 1994, "Fast contact force computation for
// nonpenetrating rigid bodies") solves contact forces by pivoting instead. This method does so
// with Lemke's pivoting on the MLCP with Coulomb friction (constraints/exact_mlcp.h), one island
// at a time (islands.h): each island's λ is the exact solution of its rows, friction included,
// and a chain of joints alone is one linear solve. It is the ground truth chapter 6 measures
// PGS's λ against, sweep by sweep.
//
// What it does not do exactly, and says so: an island with more than exact_island_limit LCP
// variables (a pyramid of 20) is solved by PGS as `pgs` would, and so is one where Lemke ends in a
// ray (friction makes the LCP's matrix indefinite; about 1 random MLCP in 300 in the tests). The
// rest of the step is `pgs`'s: split impulse with its slop, restitution, the contact cache.
#pragma once

#include <memory>

#include "contact/step_method.h"

namespace lamina {

std::unique_ptr<StepMethod> make_exact_method();

}  // namespace lamina
