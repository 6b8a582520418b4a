// Projected Gauss-Seidel for the MLCP of eq. 3-24 (chapter 3, "Projected Gauss-Seidel Method").
//
//   start    a = B λ_exp                        (the text's TransposeMultiply)
// (The pitfalls lambda-b1 and clamp-increment put back two classic slips when asked.)
//   sweep    for each row i:
//              Δ = (η_i − J_i · a) / d_i        (Gauss-Seidel's (b_i − Σ_j A_ij λ_j) / A_ii)
//              λ_i ← clamp(λ_i + Δ, λ⁻_i, λ⁺_i)  (friction rows: ±μ λc of their contact row's
//                                                current λ, eq. 3-26)
//              a ← a + (λ_i new − old) B_i
// The text's pseudo-code with its two faults mended: TransposeMultiply scales by λ[i] (the text
// writes λ[b1], λ[b2]), and a one-body row (Jmap[1] = −1) never reads a[−1].
//
// On more than one thread (use_workers) the rows are cut into two parts a thread, each a run of
// consecutive rows, and thread t of T sweeps parts t and 2T − 1 − t, sweep after sweep (below:
// why these two; every other piece of a step takes its runs so, runs_of_thread). A row waits
// only where the row before it on one of its bodies, in the one-thread order (this sweep's, or
// the sweep before's), belongs to another part: until that part has swept it (its own thread's
// other part, or another thread's). So every a_b a row reads holds the value it holds in the
// one-thread order, and so does every λ (a friction row's contact rows are on its bodies): λ is
// the same bit for bit on any number of threads. Contact rows come in the order of their bodies'
// indices, so in a scene built bottom up (a pyramid, a stack) a part shares bodies with the parts
// next to it only along one cut, and the parts run as a wavefront: part p starts a pass once
// part p − 1 has passed its last rows, on the bodies of their cut, so it runs about a pass behind
// p − 1. Taken from both ends of the wavefront, a thread's parts are one that starts early and
// one that starts late; taken side by side (parts 2t, 2t + 1), the last thread had both late
// ones and the others waited for it at the end (pyramid:80's MLCPs on two threads: the velocity
// solve 11 % and the position solve 20 % faster from both ends; docs/performance.md).
// The cut and the waits (part_plan.h) are kept from solve to solve while the rows' groups stay
// the same, as a resting pile's do.
//
// Two MLCPs that share no λ (a step's velocity MLCP and split impulse's position MLCP, whose ζ
// does not depend on the velocity λ) can be solved side by side (solve_both): each thread then
// has two lanes of each, and takes the second MLCP's where the first's wait — at the wavefront's
// fill and drain, where a thread used to wait for a part a pass behind or ahead of its own.
// Each MLCP's rows are swept in the order solve() sweeps them, so λ is the same bit for bit.
//
// A thread's two parts are two lanes: its sweeps take a group of each lane at once where neither
// waits on the other (pass_two_groups: their rows interleaved, two independent chains of
// arithmetic that the processor overlaps), and a group alone where one does; the waits are
// looked at once per run of groups that cannot wait (PartPlan::run_end), not once per group.
// On one thread the same plan with two parts gives the one thread two lanes. The rows of one
// lane still follow each other, and each group still comes after every group before it on its
// bodies, so λ is again the one-thread λ bit for bit; a sweep is bound by the latency of each
// row's chain (the dot product, the clamp, the update of a), and two chains at once take little
// longer than one.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "constraints/mlcp.h"
#include "constraints/part_plan.h"
#include "constraints/sweep_settings.h"
#include "motion/pitfalls.h"
#include "parallel/workers.h"

namespace lamina {

// Row i of a sweep (eq. 3-24), on the a_b = (B λ)_b of its two bodies (a2 unused for a one-body
// row): Δ = (η_i − J_i · a) / d_i, λ_i ← clamp(λ_i + Δ, λ⁻_i, λ⁺_i), a ← a + (λ_i new − old) B_i.
// The one row update of every sweep (PgsSolver's, chapter 6's block sweep).
// With ClampIncrement (the pitfall clamp-increment) the increment Δ is clamped to [λ⁻, λ⁺]
// instead of λ_i + Δ, so λ_i itself may leave its bounds.
template <int N, bool ClampIncrement = false>
void pgs_row(const PackedRow<N>& row, std::size_t i, double* lambda, Block<N>& a1, Block<N>& a2) {
  const bool two_bodies = row.two_bodies();
  // Δ = (η_i − J_i · a) / d_i; 1/d_i is computed once per row when the row is assembled, so the
  // sweep multiplies instead of dividing
  const double delta = (row.eta - row_dot<N>(row.J, a1, a2, two_bodies)) * row.inverse_d;
  const double old = lambda[i];
  const auto [lo, hi] = bounds_of(row, lambda);
  if constexpr (ClampIncrement) {
    lambda[i] = old + std::max(lo, std::min(delta, hi));
  } else {
    lambda[i] = std::max(lo, std::min(old + delta, hi));
  }
  const double diff = lambda[i] - old;
  a1 += diff * row.B[0];
  if (two_bodies) a2 += diff * row.B[1];
}

// What a pass over one group of rows does: a PGS sweep of its rows, or (on threads, before the
// first sweep) its rows' terms of a = B λ.
enum class GroupPass { sweep, transpose };

// One pass over the rows [first, last) of one group, on the same bodies (a pair's contact rows
// and their friction rows): the group keeps its bodies' a_b in local variables, the same
// arithmetic as row by row through memory, without a trip through memory per row. Raw
// pointers: the stores to λ cannot then be taken to move the vectors' buffers.
template <int N, bool ClampIncrement, GroupPass What>
void pass_group(const PackedRow<N>* rows, int first, int last, Block<N>* a, double* lambda) {
  const int b1 = rows[first].map[0];
  const int b2 = rows[first].map[1];
  Block<N> a1 = a[b1];
  Block<N> a2 = b2 >= 0 ? a[b2] : Block<N>::Zero();
  for (int i = first; i < last; ++i) {
    if constexpr (What == GroupPass::sweep) {
      pgs_row<N, ClampIncrement>(rows[i], static_cast<std::size_t>(i), lambda, a1, a2);
    } else {
      add_row_term(rows[i], lambda[i], a1, a2);
    }
  }
  a[b1] = a1;
  if (b2 >= 0) a[b2] = a2;
}

// PGS's working memory, a = B λ per body, kept from solve to solve so that a World step
// allocates nothing once its buffers have grown.
class PgsSolver {
 public:
  // Up to settings.iterations sweeps on λ in place (λ holds λ_exp on entry). After each sweep,
  // when sweeps are recorded or a tolerance is set, measures mlcp.residual(λ), records it and λ if
  // asked and stops once it is ≤ a tolerance > 0. Recording alone never changes the sweeps run,
  // so λ is the same bit for bit with or without it. result.iterations, result.residuals and
  // result.lambdas are filled; result.lambda is left alone.
  // Of the pitfalls (motion/pitfalls.h), lambda-b1 and clamp-increment are read here.
  // With `forces_to`, F_c = Jᵀ λ (eq. 3-11) of the λ solved is then added to those bodies'
  // forces and torques, the sums of Mlcp::add_constraint_forces bit for bit: where the sweeps
  // run in parts, in the last sweep, each group's terms as soon as its λ are final (its rows
  // still at hand, not read again in a pass of their own); else after the sweeps.
  void solve(const Mlcp& mlcp, double* lambda, const SweepSettings& settings, SweepResult& result,
             Pitfalls pitfalls = {}, std::vector<RigidBody>* forces_to = nullptr);
  // solve(first, …) and then solve(second, …), the same λ of each bit for bit, for two MLCPs on
  // the same bodies whose λ are independent: side by side (above) when both would be swept in
  // parts (on threads, or in two lanes) and neither is measured; else one after the other.
  // velocity_change() is then the second's; `forces_to` takes the first's F_c, as solve's does.
  void solve_both(const Mlcp& first, double* first_lambda, const SweepSettings& first_settings,
                  SweepResult& first_result, const Mlcp& second, double* second_lambda,
                  const SweepSettings& second_settings, SweepResult& second_result,
                  Pitfalls pitfalls = {}, std::vector<RigidBody>* forces_to = nullptr);

  // (B λ)_b after the last sweep of the last solve: body b's velocity change per Δt from the
  // rows, [v; ω].
  Vec6 velocity_change(int body) const;

  // Sweeps on the threads of `workers` from now on (above) when a solve runs every sweep (no
  // tolerance, nothing recorded), has rows enough and parts that seldom wait on each other;
  // otherwise, or with nullptr or one thread, on the calling thread. The same λ either way.
  // `workers` must outlive the solves.
  void use_workers(Workers* workers);
  // Whether the last solve swept on the workers' threads.
  bool swept_on_threads() const { return swept_on_threads_; }
  // Whether the last solve_both swept its two MLCPs side by side.
  bool swept_side_by_side() const { return swept_side_by_side_; }
  // Whether the last solve swept on one thread in two lanes (above).
  bool swept_in_lanes() const { return swept_in_lanes_; }
  // The rows an MLCP needs to be swept in parts (and then only when they seldom wait on each
  // other: PartPlan::usable): on threads, whose hand-overs take microseconds, and in two lanes on
  // one thread, which cost a plan and a few instructions a group. Below 48 rows the lanes gained
  // nothing (vertical-stack:12 and :14, 36 and 42 rows); from 48 they took 10–26 % off the solve
  // (vertical-stack:16 and :20, 48 and 60 rows; pyramid:10, 399: docs/performance.md).
  static constexpr int threads_min_rows = 512;
  static constexpr int lanes_min_rows = 48;
  // How many times a plan of the parts has been made (PartPlan): once per MLCP that neither of
  // the last two plans serves (its groups on other bodies).
  long plans_made() const { return plans_made_; }

 private:
  template <int N>
  std::vector<Block<N>>& a();
  template <int N>
  std::vector<Block<N>>& first_a_of();  // solve_both's first MLCP's a
  // The rows' groups cut into `parts` parts and the waits between them (plan_, kept or made);
  // false when the rows are too few or would wait too often (then one thread and one lane are
  // faster).
  bool plan_parts(const Mlcp& mlcp, int parts);
  template <int N, bool ClampIncrement>
  void sweep(const PackedRows<N>& rows, const std::vector<RowGroup>& groups,
             std::vector<Block<N>>& a_of_body, double* lambda) const;
  // An MLCP as its lanes sweep it (below); the lanes are pgs_lanes.cpp's.
  template <int N>
  struct Swept;
  template <int N, bool ClampIncrement>
  void sweep_in_lanes(const Swept<N>* swept, int count, int t) const;
  // The sweeps of `count` MLCPs (one, or two side by side) on the workers' threads.
  template <int N, bool ClampIncrement>
  void solve_on_threads(Swept<N>* swept, int count);
  template <int N>
  Swept<N> swept(const Mlcp& mlcp, const PackedRows<N>& rows, std::vector<Block<N>>& a_of_body,
                 double* lambda, int sweeps, int index) const;

  bool planar_ = true;                 // the layout of the last solve
  bool swept_on_threads_ = false;      // how the last solve swept
  bool swept_in_lanes_ = false;
  bool swept_side_by_side_ = false;
  std::vector<Block<3>> planar_a_;     // a in the planar layout
  std::vector<Block<6>> general_a_;    // a in the general layout
  std::vector<Block<3>> first_planar_a_;   // solve_both's first MLCP's a, in each layout (the
  std::vector<Block<6>> first_general_a_;  // second's is the last solve's: planar_a_, general_a_)
  Workers* workers_ = nullptr;            // the threads, or none
  // per MLCP swept at once and per part: k·G + g + 1 once its pass k took group g
  std::unique_ptr<Progress[]> progress_;
  int progress_count_ = 0;  // progress_'s counters, kept while the solves are on one thread
  // The last two plans made (a step's velocity plan serves its position MLCP too, unless joints'
  // rows add groups to the velocity MLCP alone), and the one the current solve sweeps by.
  std::array<PartPlan, 2> plans_;
  const PartPlan* plan_ = nullptr;
  long plans_made_ = 0;
};

// An MLCP as a thread's lanes sweep it: its rows, groups, a and λ, the plan of its parts, each
// part's Progress (nullptr on one thread), the pass its lanes start at (0: a = B λ first) and
// the sweeps.
template <int N>
struct PgsSolver::Swept {
  const PackedRow<N>* rows = nullptr;
  const RowGroup* groups = nullptr;
  long group_count = 0;
  Block<N>* a = nullptr;
  double* lambda = nullptr;
  const PartPlan* plan = nullptr;
  Progress* progress = nullptr;
  long first_pass = 1;
  int sweeps = 0;
  RigidBody* forces_to = nullptr;  // bodies given F_c = Jᵀ λ in the last sweep, or nullptr
};

// Solves the MLCP from the guess λ_exp (warm start) in a solver of its own; a caller solving
// every step keeps a PgsSolver instead.
SweepResult solve_pgs(const Mlcp& mlcp, const Eigen::VectorXd& lambda_exp,
                      const SweepSettings& settings);

}  // namespace lamina
