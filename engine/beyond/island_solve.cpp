#include "beyond/island_solve.h"

#include <cmath>

namespace lamina {

namespace {

// The island's own MLCP and λ: an island of every row is the MLCP itself, solved in place with
// nothing copied (a pyramid); else its rows assembled apart, their λ copied into work.lambda.
struct Own {
  const Mlcp& mlcp;
  double* lambda;
};
Own own_of(const Mlcp& mlcp, const Island& island, IslandWorkspace& work,
           std::vector<double>& lambda) {
  const bool whole = static_cast<int>(island.rows.size()) == mlcp.row_count();
  work.lambda.clear();
  if (whole) return {mlcp, lambda.data()};
  work.mlcp.assemble_subset(mlcp, island.rows);
  for (const int r : island.rows) work.lambda.push_back(lambda[static_cast<std::size_t>(r)]);
  return {work.mlcp, work.lambda.data()};
}

// An island assembled apart: its λ back into the step's (nothing for an island of every row).
void copy_back(const Island& island, const IslandWorkspace& work, std::vector<double>& lambda) {
  for (std::size_t i = 0; i < work.lambda.size(); ++i) {
    lambda[static_cast<std::size_t>(island.rows[i])] = work.lambda[i];
  }
}

}  // namespace

IslandSolve solve_island(const Mlcp& mlcp, const Island& island, int sweeps, IslandWorkspace& work,
                         PgsSolver& pgs, std::vector<double>& lambda, Pitfalls pitfalls,
                         bool try_exact) {
  const Own own = own_of(mlcp, island, work, lambda);
  IslandSolve how = IslandSolve::pgs;
  // A state gone non-finite is left to PGS, which carries it into the bodies, where the run
  // that diverged is stopped and says so (first_non_finite_body); pivoting would refuse it.
  const auto finite = [&] {
    for (int i = 0; i < own.mlcp.row_count(); ++i) {
      if (!std::isfinite(own.mlcp.eta(i)) || !std::isfinite(own.mlcp.d(i))) return false;
    }
    return true;
  };
  if (try_exact && island.lcp_size <= exact_island_limit && finite() &&
      has_exact_form(own.mlcp)) {
    if (work.exact.solve(own.mlcp) == LemkeStatus::solved) {
      for (int i = 0; i < own.mlcp.row_count(); ++i) own.lambda[i] = work.exact.lambda()[i];
      how = IslandSolve::exact;
    }
  }
  if (how == IslandSolve::pgs) {
    SweepResult sweeps_run;
    pgs.solve(own.mlcp, own.lambda, {sweeps, 0.0, false}, sweeps_run, pitfalls);
  }
  copy_back(island, work, lambda);
  return how;
}

bool solve_island_beside(const Mlcp& mlcp, const Island& island, int sweeps,
                         IslandWorkspace& work, PgsSolver& pgs, std::vector<double>& lambda,
                         SplitImpulse& split, int position_sweeps, std::vector<RigidBody>& bodies,
                         Pitfalls pitfalls) {
  const Own own = own_of(mlcp, island, work, lambda);
  // an island of every row is the MLCP itself: its F_c is the whole step's
  const bool whole = &own.mlcp == &mlcp;
  SweepResult island_sweeps;
  SweepResult position_sweeps_run;
  pgs.solve_both(own.mlcp, own.lambda, {sweeps, 0.0, false}, island_sweeps, split.position(),
                 split.lambda().data(), {position_sweeps, 0.0, false}, position_sweeps_run,
                 pitfalls, whole ? &bodies : nullptr);
  copy_back(island, work, lambda);
  return whole;
}

void finish_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                 const std::vector<double>& lambda, const std::vector<unsigned char>& skip,
                 SplitImpulse& split, PgsSolver& pgs, WorldReport* report,
                 bool push_out_taken, bool forces_added) {
  const WorldSettings& s = problem.settings;
  if (!push_out_taken) {
    split.solve(problem.velocity, problem.pairs, s.contact, s.step, s.position_iterations, pgs,
                report != nullptr ? &report->position : nullptr, problem.workers);
  }
  // eq. 3-11, 5-9: F_c = Jᵀ λ (nothing on a skipped body: its rows' λ are zero here); with
  // workers, each thread adds to and steps its own runs of the bodies, as the World's step does
  if (!forces_added) problem.velocity.add_constraint_forces(bodies, lambda.data(), problem.workers);
  // eq. 2-1..2-8 under F_ext + F_c, with the push-out
  integrate_with_push_out(bodies, split.push_out(), s.step.dt, s.step.pitfalls, problem.workers,
                          skip);
}

}  // namespace lamina
