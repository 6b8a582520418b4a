// `block`: PGS with each two-point manifold's two contact rows solved together, exactly (Box2D
// 2.4's block solver, b2ContactSolver::SolveVelocityConstraints; Catto, "Modeling and Solving
// Constraints", GDC 2009).
//
// Two contact points of one pair push on the same two bodies, so their rows are strongly coupled
// (a box resting flat: J B's off-diagonal entry is about half the diagonal), and row-by-row PGS
// shares the load between them slowly; a heavy box on a light one needs hundreds of sweeps. For
// the two rows alone, eq. 3-24 is a 2 × 2 LCP that has four candidate answers:
//   both pushing       x = A⁻¹(−b) ≥ 0
//   only the first     x = (−b₁/A₁₁, 0),  w₂ = A₂₁ x₁ + b₂ ≥ 0
//   only the second    x = (0, −b₂/A₂₂),  w₁ = A₁₂ x₂ + b₁ ≥ 0
//   neither            x = 0,             b ≥ 0
// with A = the pair's 2 × 2 block of J B and b = W − A λ (W = J B λ − η, eq. 3-23, the slack
// with the pair's own λ taken out). The first that holds is the pair's exact answer given every
// other row; a block so near singular that A's condition passes 1000 (Box2D's bound) is swept
// row by row instead. Everything else is `pgs`'s: friction rows swept between, split impulse,
// restitution, the cache.
#pragma once

#include <functional>
#include <memory>

#include "constraints/mlcp.h"
#include "contact/step_method.h"

namespace lamina {

// `sweeps` block sweeps on λ in place (λ_exp on entry), calling after_sweep(k, λ) after sweep k
// (k from 1) when given: the method's solve, and chapter 6's λ-per-sweep plots.
void block_sweeps(const Mlcp& mlcp, double* lambda, int sweeps,
                  const std::function<void(int, const double*)>& after_sweep = {});

std::unique_ptr<StepMethod> make_block_method();

}  // namespace lamina
