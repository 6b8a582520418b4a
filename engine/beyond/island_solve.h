// What chapter 6's methods share around their own solve of the velocity MLCP: an island solved
// exactly or, past a size or when Lemke gives up, by PGS; and steps 6–7 after the solve, as the
// World takes them (split impulse's push-out, F_c = Jᵀ λ, chapter 2's step).
#pragma once

#include <vector>

#include "beyond/islands.h"
#include "constraints/exact_mlcp.h"
#include "constraints/mlcp.h"
#include "constraints/pgs_solver.h"
#include "contact/split_impulse.h"
#include "contact/step_method.h"

namespace lamina {

// How an island's λ was found.
enum class IslandSolve { exact, pgs };

// The memory an island's solve works in: kept by a method from step to step, one for each
// island number, so that a steady step (its islands the same sizes as the step before) solves
// them without allocating.
struct IslandWorkspace {
  Mlcp mlcp;                   // the island's own MLCP, when it is not every row
  std::vector<double> lambda;  // its λ
  ExactMlcpSolver exact;       // its exact solve
};

// Solves the island's rows of `mlcp` (its MLCP, eq. 3-24, on its own: islands.h) into their λ:
// exactly (exact_mlcp.h) when the island has at most exact_island_limit variables and the solve
// ends in a solution, else by `sweeps` PGS sweeps from the λ there (with the PGS pitfalls).
// Rows the exact form cannot take (a friction row with fixed bounds: crude-friction) go to PGS
// too, and so does every island when `try_exact` is false. `work` and `pgs` are working memory.
IslandSolve solve_island(const Mlcp& mlcp, const Island& island, int sweeps, IslandWorkspace& work,
                         PgsSolver& pgs, std::vector<double>& lambda, Pitfalls pitfalls = {},
                         bool try_exact = true);

// An island that PGS sweeps (more variables than exact_island_limit), swept beside split
// impulse's position MLCP, made ready by split.prepare() (PgsSolver::solve_both: the position
// MLCP's parts fill the island's waits on threads). The island's λ and the position MLCP's are
// those of two solves one after the other, bit for bit; `pgs`'s last solve is then the
// position MLCP's, so that split.take_push_out() reads it. An island of every row (a pile) adds
// F_c = Jᵀ λ of all of them to `bodies` as it is swept (PgsSolver::solve_both's `forces_to`),
// and says so: true when finish_step is then to add none.
bool solve_island_beside(const Mlcp& mlcp, const Island& island, int sweeps,
                         IslandWorkspace& work, PgsSolver& pgs, std::vector<double>& lambda,
                         SplitImpulse& split, int position_sweeps, std::vector<RigidBody>& bodies,
                         Pitfalls pitfalls = {});

// Steps 6 and 7 after the velocity solve: the split-impulse push-out (when the settings ask for
// it, recorded in the report; unless `push_out_taken`, the method having taken it already:
// solve_island_beside), F_c = Jᵀ λ (unless `forces_added`: solve_island_beside) and chapter
// 2's step for every body whose `skip` entry is 0 (skip empty: every body); a skipped body
// (advanced by the method itself) only has its forces cleared.
void finish_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                 const std::vector<double>& lambda, const std::vector<unsigned char>& skip,
                 SplitImpulse& split, PgsSolver& pgs, WorldReport* report,
                 bool push_out_taken = false, bool forces_added = false);

}  // namespace lamina
