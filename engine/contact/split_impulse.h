// Split impulse (beyond the text; docs/ch4-contact-model.md, "Beyond the text"): after the
// velocity MLCP, the same contact rows are solved once more for a push-out velocity V_p that each
// body keeps for the position update of this step only, so that a penetration is undone without
// the velocity remembering it (Baumgarte's bias, eq. 4-4, puts it into V and it bounces back).
//
//   rows  each contact's contact row of the velocity MLCP, asking J V_p ≥ its push-out ζ
//         (position_targets, contact_rows.h)
//   solve eq. 3-16 for bodies at rest under no force: η = ζ/Δt, by PGS
//   V_p   = M⁻¹ Jᵀ λ Δt = B λ Δt per body
// The World's step and chapter 6's methods (engine/beyond/) both take their position update from
// here, and their integration from integrate_with_push_out.
#pragma once

#include <vector>

#include "constraints/mlcp.h"
#include "constraints/pgs_solver.h"
#include "constraints/step_report.h"
#include "contact/contact.h"
#include "contact/contact_rows.h"

namespace lamina {

class SplitImpulse {
 public:
  // Solves the position MLCP of the pairs' contact rows of `velocity` with `iterations` PGS
  // sweeps, recording into `report` when one is given. Nothing is solved, and push_out() is
  // empty, when the correction is not split impulse or (without a report) no point is deeper
  // than the slop and no gap is to close. With `workers` the position MLCP is packed on their
  // threads (the sweeps run where `pgs` runs them: PgsSolver::use_workers).
  void solve(const Mlcp& velocity, const std::vector<ContactPair>& pairs,
             const ContactSettings& contact, const StepSettings& step, int iterations,
             PgsSolver& pgs, StepReport* report, Workers* workers = nullptr);

  // solve() in three steps, for a caller that solves the position MLCP itself (the World's
  // step solves it beside the velocity MLCP: its ζ does not depend on the velocity λ).
  // 1. The position MLCP made ready, λ = 0: false, and push_out() empty, when solve() would
  // solve nothing (`reporting`: a report is being made, which shows the sweeps all the same).
  bool prepare(const Mlcp& velocity, const std::vector<ContactPair>& pairs,
               const ContactSettings& contact, const StepSettings& step, bool reporting,
               Workers* workers = nullptr);
  // 2. The MLCP to solve, and its λ, solved in place.
  const Mlcp& position() const { return position_; }
  std::vector<double>& lambda() { return lambda_; }
  // 3. Each body's push-out from the solution, `pgs`'s last solve having been the position
  // MLCP's (its B λ).
  void take_push_out(const PgsSolver& pgs, double dt, Workers* workers = nullptr);
  // Each body's push-out [v; ω] in m/s and rad/s, or empty for none.
  const std::vector<Vec6>& push_out() const { return push_out_; }

 private:
  std::vector<int> rows_;        // each contact's row in the velocity MLCP
  std::vector<double> zeta_;     // and the push-out ζ of its position row, in m/s
  Mlcp position_;                // the position MLCP: those rows of the velocity MLCP
  std::vector<double> lambda_;   // its λ, in N
  std::vector<Vec6> push_out_;   // per body, m/s and rad/s
};

// Chapter 2's step (eq. 2-1..2-8) for every dynamic body under its accumulated forces, with the
// push-out velocity (empty: none) lent for the position update and then taken back; every
// body's forces are cleared. The pitfalls go to chapter 2's step. With `workers`, each thread
// steps a run of the bodies (each body's step is its own). A body whose `skip` entry is not 0
// (skip empty: none; a body a chapter-6 method has advanced itself) only has its forces cleared.
void integrate_with_push_out(std::vector<RigidBody>& bodies, const std::vector<Vec6>& push_out,
                             double dt, Pitfalls pitfalls = {}, Workers* workers = nullptr,
                             const std::vector<unsigned char>& skip = {});
// The same for one body with its push-out `push` ([v; ω], zero for none).
void integrate_with_push_out(RigidBody& body, const Vec6& push, double dt, Pitfalls pitfalls = {});

// PGS on λ in place, λ_exp on entry; with a report (`into`), also records the MLCP as solved,
// λ_exp, the residual after every sweep and λ. With `forces_to`, F_c = Jᵀ λ is added to those
// bodies (PgsSolver::solve).
void solve_recording(PgsSolver& pgs, const Mlcp& mlcp, int iterations, std::vector<double>& lambda,
                     StepReport* into, Pitfalls pitfalls = {},
                     std::vector<RigidBody>* forces_to = nullptr);

}  // namespace lamina
