#include "beyond/island_solve.h"

#include <cmath>

namespace lamina {

IslandSolve solve_island(const Mlcp& mlcp, const Island& island, int sweeps, IslandWorkspace& work,
                         PgsSolver& pgs, std::vector<double>& lambda, Pitfalls pitfalls,
                         bool try_exact) {
  // An island of every row is the MLCP itself: solved in place, nothing copied (a pyramid)
  const bool whole = static_cast<int>(island.rows.size()) == mlcp.row_count();
  if (!whole) work.mlcp.assemble_subset(mlcp, island.rows);
  const Mlcp& own = whole ? mlcp : work.mlcp;
  std::vector<double>& local = work.lambda;
  local.clear();
  if (!whole) {
    for (const int r : island.rows) local.push_back(lambda[static_cast<std::size_t>(r)]);
  }
  double* own_lambda = whole ? lambda.data() : local.data();
  IslandSolve how = IslandSolve::pgs;
  // A state gone non-finite is left to PGS, which carries it into the bodies, where the run
  // that diverged is stopped and says so (first_non_finite_body); pivoting would refuse it.
  const auto finite = [&] {
    for (int i = 0; i < own.row_count(); ++i) {
      if (!std::isfinite(own.eta(i)) || !std::isfinite(own.d(i))) return false;
    }
    return true;
  };
  if (try_exact && island.lcp_size <= exact_island_limit && finite() && has_exact_form(own)) {
    if (work.exact.solve(own) == LemkeStatus::solved) {
      for (int i = 0; i < own.row_count(); ++i) own_lambda[i] = work.exact.lambda()[i];
      how = IslandSolve::exact;
    }
  }
  if (how == IslandSolve::pgs) {
    SweepResult sweeps_run;
    pgs.solve(own, own_lambda, {sweeps, 0.0, false}, sweeps_run, pitfalls);
  }
  for (std::size_t i = 0; i < local.size(); ++i) lambda[static_cast<std::size_t>(island.rows[i])] = local[i];
  return how;
}

void finish_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                 const std::vector<double>& lambda, const std::vector<unsigned char>& skip,
                 SplitImpulse& split, PgsSolver& pgs, WorldReport* report) {
  const WorldSettings& s = problem.settings;
  split.solve(problem.velocity, problem.pairs, s.contact, s.step, s.position_iterations, pgs,
              report != nullptr ? &report->position : nullptr, problem.workers);
  // eq. 3-11, 5-9: F_c = Jᵀ λ (nothing on a skipped body: its rows' λ are zero here)
  problem.velocity.add_constraint_forces(bodies, lambda.data());
  const std::vector<Vec6>& push = split.push_out();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!skip.empty() && skip[b]) {
      bodies[b].clear_forces();  // advanced already: its F_c was taken in its own steps
      continue;
    }
    // eq. 2-1..2-8 under F_ext + F_c, with the push-out
    integrate_with_push_out(bodies[b], push.empty() ? Vec6::Zero() : push[b], s.step.dt,
                            s.step.pitfalls);
  }
}

}  // namespace lamina
