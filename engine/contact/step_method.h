// The seam through which chapter 6's methods (engine/beyond/) take a World's step their own way.
//
// A World does steps 1–4 of its step (forces, collision, cache, rows) and assembles the rows'
// MLCP (eq. 3-16) the same way whatever the method. Then either it does steps 5–7 itself — the
// text's PGS, split impulse, F_c = Jᵀ λ, chapter 2's step: the methods `text` and `pgs` — or it
// hands them to the StepMethod of its settings, which solves the MLCP its own way and advances
// the bodies to t + Δt. The World then keeps the λ the method returns as the warm start of the
// next step (the contact cache's λ, the joints' λ), as it keeps PGS's.
#pragma once

#include <cstddef>
#include <vector>

#include "constraints/constraint.h"
#include "constraints/mlcp.h"
#include "contact/world.h"

namespace lamina {

// What steps 1–4 made, read-only.
struct StepProblem {
  const WorldSettings& settings;
  std::size_t first_joint_row;              // step 4's rows (velocity's): each pair's contact
                                            // and friction rows, then from here the joints'
  const std::vector<ContactPair>& pairs;    // the contacts, with their row map
  const std::vector<const Constraint*>& joints;  // the joints, in the order added
  const std::vector<RowRange>& joint_rows;  // and where each one's rows sit
  const Mlcp& velocity;                     // the rows' MLCP, assembled (eq. 3-16)
  Workers* workers = nullptr;               // the World's threads past the first, or none:
                                            // for PGS's sweeps (PgsSolver::use_workers)
};

class StepMethod {
 public:
  virtual ~StepMethod() = default;
  // Steps 5–7: solves the velocity MLCP into `lambda` (the warm start λ_exp on entry, as step 4
  // wrote it) and advances `bodies` (at t, their forces F_ext accumulated) to t + Δt, clearing
  // their forces. With a report, fills report->velocity.solution.residuals with the residual
  // after each round of the method (its sweeps, or one entry for a direct solve) and
  // report->position with its position MLCP, if it has one; the World records the rest.
  virtual void take_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                         std::vector<double>& lambda, WorldReport* report) = 0;
};

}  // namespace lamina
