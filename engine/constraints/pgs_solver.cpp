#include "constraints/pgs_solver.h"

#include <algorithm>
#include <stdexcept>

namespace lamina {
namespace {

// What a pass over one group of rows does: a PGS sweep of its rows, or (on threads, before the
// first sweep) its rows' terms of a = B λ.
enum class Pass { sweep, transpose };

// One pass over the rows [first, last) of one group, on the same bodies (a pair's contact rows
// and their friction rows): the group keeps its bodies' a_b in local variables, the same
// arithmetic as row by row through memory, without a trip through memory per row. Raw
// pointers: the stores to λ cannot then be taken to move the vectors' buffers.
template <int N, bool ClampIncrement, Pass What>
void pass_group(const PackedRow<N>* rows, int first, int last, Block<N>* a, double* lambda) {
  const int b1 = rows[first].map[0];
  const int b2 = rows[first].map[1];
  Block<N> a1 = a[b1];
  Block<N> a2 = b2 >= 0 ? a[b2] : Block<N>::Zero();
  for (int i = first; i < last; ++i) {
    if constexpr (What == Pass::sweep) {
      pgs_row<N, ClampIncrement>(rows[i], static_cast<std::size_t>(i), lambda, a1, a2);
    } else {
      add_row_term(rows[i], lambda[i], a1, a2);
    }
  }
  a[b1] = a1;
  if (b2 >= 0) a[b2] = a2;
}

// One pass over two groups at once, of different lanes and on different bodies: row j of the
// first group, then row j of the second, each the arithmetic of pgs_row on its own group's a_b,
// so that the two chains of arithmetic overlap (a group has one to three rows).
template <int N, bool ClampIncrement>
[[gnu::always_inline]] inline void pass_two_groups(const PackedRow<N>* rows, const RowGroup* group,
                                                   int first, int second, Block<N>* a,
                                                   double* lambda) {
  const int b1 = rows[group[first].first].map[0];
  const int b2 = rows[group[first].first].map[1];
  const int c1 = rows[group[second].first].map[0];
  const int c2 = rows[group[second].first].map[1];
  Block<N> a1 = a[b1];
  Block<N> a2 = b2 >= 0 ? a[b2] : Block<N>::Zero();
  Block<N> e1 = a[c1];
  Block<N> e2 = c2 >= 0 ? a[c2] : Block<N>::Zero();
  int i = group[first].first;
  int j = group[second].first;
  const int i_end = group[first + 1].first;
  const int j_end = group[second + 1].first;
  for (; i < i_end && j < j_end; ++i, ++j) {
    pgs_row<N, ClampIncrement>(rows[i], static_cast<std::size_t>(i), lambda, a1, a2);
    pgs_row<N, ClampIncrement>(rows[j], static_cast<std::size_t>(j), lambda, e1, e2);
  }
  for (; i < i_end; ++i) {
    pgs_row<N, ClampIncrement>(rows[i], static_cast<std::size_t>(i), lambda, a1, a2);
  }
  for (; j < j_end; ++j) {
    pgs_row<N, ClampIncrement>(rows[j], static_cast<std::size_t>(j), lambda, e1, e2);
  }
  a[b1] = a1;
  if (b2 >= 0) a[b2] = a2;
  a[c1] = e1;
  if (c2 >= 0) a[c2] = e2;
}

// Whether λ is zero in every row (split impulse's position solve starts there): then a = B λ is
// zero without reading a row (each row's term would be skipped: add_row_term), and on threads
// the pass that makes it is skipped too.
bool all_zero(const double* lambda, int count) {
  return std::all_of(lambda, lambda + count, [](double l) { return l == 0.0; });
}

// The rows are swept in parts (threads, lanes) when there are a few hundred rows, and when the
// parts seldom wait on each other (PartPlan::usable).
constexpr int threaded_min_rows = 512;

// The pitfall lambda-b1: the text's TransposeMultiply as written, scaling row i's blocks by
// λ[b1] and λ[b2], λ indexed by body instead of by row. Where a body index is past the rows the
// text reads beyond λ; here it wraps round to row b mod s, so the slip stays a wrong number and
// not a crash.
template <int N>
void transpose_multiply_text_slip(const PackedRows<N>& rows, int body_count, const double* lambda,
                                  std::vector<Block<N>>& a) {
  a.assign(static_cast<std::size_t>(body_count), Block<N>::Zero());
  const std::size_t s = rows.size();
  for (std::size_t i = 0; i < s; ++i) {
    const PackedRow<N>& row = rows[i];
    a[row.map[0]] += lambda[static_cast<std::size_t>(row.map[0]) % s] * row.B[0];
    if (row.two_bodies()) {
      a[row.map[1]] += lambda[static_cast<std::size_t>(row.map[1]) % s] * row.B[1];
    }
  }
}

}  // namespace

template <>
std::vector<Block<3>>& PgsSolver::a<3>() { return planar_a_; }
template <>
std::vector<Block<6>>& PgsSolver::a<6>() { return general_a_; }

void PgsSolver::use_workers(Workers* workers) {
  if (workers == nullptr || workers->count() < 2) workers = nullptr;
  if (workers == workers_) return;
  workers_ = workers;
  progress_.reset(workers_ != nullptr ? new Progress[runs_on(workers_)] : nullptr);  // per part
}

bool PgsSolver::plan_parts(const Mlcp& mlcp, int parts) {
  if (mlcp.row_count() < threaded_min_rows || !mlcp.friction_on_own_bodies()) return false;
  // a plan kept for the MLCPs solved before, if one serves (a step's position MLCP is served by
  // its velocity MLCP's plan), else a new one in place of the older
  for (PartPlan& plan : plans_) {
    if (!plan.serves(mlcp, parts)) continue;
    plan_ = &plan;
    return plan.usable();
  }
  PartPlan& older = plan_ == &plans_[0] ? plans_[1] : plans_[0];
  plan_ = &older;
  ++plans_made_;
  return older.make(mlcp, parts);
}

// One Gauss-Seidel sweep over the rows, each λ_i projected onto its bounds, group by group.
// Flattened: the groups' passes inlined into the loop (called, they cost 6 % more
// instructions on a pyramid).
template <int N, bool ClampIncrement>
[[gnu::flatten]] void PgsSolver::sweep(const PackedRows<N>& rows,
                                       const std::vector<RowGroup>& groups,
                                       std::vector<Block<N>>& a_of_body, double* lambda) const {
  // raw pointers and the count read once: the stores to λ cannot then be taken to move them
  const RowGroup* group = groups.data();
  const std::size_t count = groups.empty() ? 0 : groups.size() - 1;  // the last entry is the end
  for (std::size_t g = 0; g < count; ++g) {
    pass_group<N, ClampIncrement, Pass::sweep>(rows.data(), group[g].first, group[g + 1].first,
                                               a_of_body.data(), lambda);
  }
}

// Passes `first_pass` to `sweeps` over the groups of parts t and P − 1 − t of the plan's P parts
// (from both ends of the wavefront: pgs_solver.h), taken as two lanes (pass 0 is a = B λ,
// passes 1, 2, … the sweeps). Each lane goes as far as its waits allow: on
// the other lane, through the lanes' own counts of groups passed; on another thread's part,
// through that part's Progress. A lane's wait is looked at only where a run of its groups starts
// (PartPlan::run_end: a group that waits starts a run, and a run ends after a group that
// another part waits for); the groups after the first of a run wait on no other part. Each step
// takes the next run of each lane that may go, both side by side as far as the shorter goes
// where both can (pass_two_groups). Each lane starts once the groups its first groups share
// bodies with have been passed (about a pass of the part before it), then the two go side by
// side. Some lane can always go, or will once another thread has got further: the first of all
// the parts' next groups in the one-thread order has every group before it on its bodies behind
// it.
template <int N, bool ClampIncrement>
[[gnu::flatten]] void PgsSolver::sweep_in_lanes(const PackedRows<N>& rows,
                                                const std::vector<RowGroup>& groups,
                                                Block<N>* a, double* lambda, int t,
                                                long first_pass, int sweeps) const {
  const RowGroup* group = groups.data();
  const PartPlan::GroupWait* waits = plan_->waits();
  const long group_count = static_cast<long>(groups.size()) - 1;
  // each lane's part, its next pass k and group g, and its count k·G + g + 1 of the last group
  // passed (when the first pass is a sweep, pass 0 was done before); an empty lane is done
  const std::array<int, 2> part = runs_of_thread(t, plan_->parts());
  std::array<long, 2> pass{first_pass, first_pass};
  std::array<int, 2> next{};
  std::array<long, 2> passed{};
  for (int u = 0; u < 2; ++u) {
    next[u] = plan_->first_group(part[u]);
    passed[u] = (first_pass - 1) * group_count + plan_->first_group(part[u] + 1);
    if (plan_->first_group(part[u]) == plan_->first_group(part[u] + 1)) pass[u] = sweeps + 1;
  }
  std::array<long, max_runs> seen{};  // the last count read from each other part (a run each)
  // 0: lane u's next group may go; −1: the lane is done; else the part it waits for, + 1
  const auto waits_for = [&](int u) {
    if (pass[u] > sweeps) return -1;
    const PartPlan::GroupWait& wait = waits[next[u]];
    for (int e = 0; e < 2; ++e) {
      const int v = wait.part[e];
      if (v < 0) continue;
      const long needed = pass[u] * group_count + wait.after[e];
      if (v == part[0] || v == part[1]) {  // this thread's other lane
        if (passed[v == part[0] ? 0 : 1] < needed) return v + 1;
      } else if (seen[v] < needed) {
        seen[v] = progress_[v].value();
        if (seen[v] < needed) return v + 1;
      }
    }
    return 0;
  };
  // lane u's next run of groups (PartPlan::run_end), cut at its part's end: the first may wait,
  // the others need not be looked at
  const auto run_length = [&](int u) {
    return std::min(plan_->run_end(next[u]), plan_->first_group(part[u] + 1)) - next[u];
  };
  const auto take = [&](int u, int n) {  // lane u's next n groups, alone
    for (int g = next[u]; g < next[u] + n; ++g) {
      if (pass[u] == 0) {
        pass_group<N, ClampIncrement, Pass::transpose>(rows.data(), group[g].first,
                                                       group[g + 1].first, a, lambda);
      } else {
        pass_group<N, ClampIncrement, Pass::sweep>(rows.data(), group[g].first,
                                                   group[g + 1].first, a, lambda);
      }
    }
  };
  const auto advance = [&](int u, int n) {  // lane u has passed its next n groups
    next[u] += n;
    passed[u] = pass[u] * group_count + next[u];
    if (progress_ != nullptr && plan_->waited_on(next[u] - 1)) {
      progress_[part[u]].publish(passed[u]);  // only its last group may be waited for
    }
    if (next[u] == plan_->first_group(part[u] + 1)) {
      next[u] = plan_->first_group(part[u]);
      ++pass[u];
    }
  };
  int waiting_turns = 0;  // looks in a row at two lanes that both wait
  while (pass[0] <= sweeps || pass[1] <= sweeps) {
    const int wait0 = waits_for(0);
    const int wait1 = waits_for(1);
    const bool go0 = wait0 == 0;
    const bool go1 = wait1 == 0;
    if (go0 && go1 && pass[0] > 0 && pass[1] > 0) {
      // the two runs side by side, as far as the shorter goes
      const int n = std::min(run_length(0), run_length(1));
      for (int k = 0; k < n; ++k) {
        pass_two_groups<N, ClampIncrement>(rows.data(), group, next[0] + k, next[1] + k, a,
                                           lambda);
      }
      advance(0, n);
      advance(1, n);
    } else if (go0 || go1) {
      for (int u = 0; u < 2; ++u) {
        if (u == 0 ? !go0 : !go1) continue;
        const int n = run_length(u);
        take(u, n);
        advance(u, n);
      }
    } else {
      // both wait, one at least on another thread's part (else the plan is wrong): look at
      // both again after a moment. Not waiting on that part alone: it may be waiting, in turn,
      // on this thread's other lane, which is free to go once its own wait is over.
      const auto other_thread = [&](int wait) {
        return wait > 0 && wait - 1 != part[0] && wait - 1 != part[1];
      };
      const bool on_other_thread = other_thread(wait0) || other_thread(wait1);
      if (!on_other_thread || progress_ == nullptr) {
        throw std::logic_error("PGS's two lanes both wait on each other: their plan is wrong");
      }
      workers_->wait_a_turn(waiting_turns);
      continue;
    }
    waiting_turns = 0;
  }
}

// On the workers' threads: a = B λ (pass 0), then `sweeps` sweeps (passes 1, 2, …), thread t
// taking parts t and 2T − 1 − t as two lanes (sweep_in_lanes), pass after pass, and waiting where
// plan_parts found a group of another thread's part before one of its own. Each part starts
// pass k once the part before it has passed the rows its first rows share bodies with: a
// wavefront, each part at most a pass behind the one before it.
template <int N, bool ClampIncrement>
void PgsSolver::solve_on_threads(const Mlcp& mlcp, const PackedRows<N>& rows,
                                 std::vector<Block<N>>& a_of_body, double* lambda, int sweeps) {
  a_of_body.assign(static_cast<std::size_t>(mlcp.body_count()), Block<N>::Zero());
  // From λ = 0 a = B λ is the zero just made: pass 0 would add no term, so it is skipped, and
  // with it the pass of the wavefront that the parts spent waiting on each other in it. Every
  // part then starts as if it had passed its groups in pass 0 (the waits read those counts).
  const bool from_zero = all_zero(lambda, mlcp.row_count());
  const long first_pass = from_zero ? 1 : 0;
  for (int p = 0; p < runs_on(workers_); ++p) {
    progress_[p].reset(from_zero ? plan_->first_group(p + 1) : 0);
  }
  workers_->run([&](int t) {
    sweep_in_lanes<N, ClampIncrement>(rows, mlcp.groups(), a_of_body.data(), lambda, t,
                                      first_pass, sweeps);
  });
}

void PgsSolver::solve(const Mlcp& mlcp, double* lambda, const SweepSettings& settings,
                      SweepResult& result, Pitfalls pitfalls) {
  const bool measure = settings.record_sweeps || settings.tolerance > 0.0;
  const bool plain = measure || pitfalls.has(Pitfall::lambda_b1);
  const bool threaded = workers_ != nullptr && !plain && plan_parts(mlcp, runs_on(workers_));
  const bool in_lanes = !threaded && !plain && settings.iterations >= 2 && plan_parts(mlcp, 2);
  const bool clamp_increment = pitfalls.has(Pitfall::clamp_increment);
  swept_on_threads_ = threaded;
  swept_in_lanes_ = in_lanes;
  mlcp.visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    planar_ = N == 3;
    std::vector<Block<N>>& a_of_body = a<N>();
    if (threaded) {
      if (clamp_increment) {
        solve_on_threads<N, true>(mlcp, rows, a_of_body, lambda, settings.iterations);
      } else {
        solve_on_threads<N, false>(mlcp, rows, a_of_body, lambda, settings.iterations);
      }
      result.iterations = settings.iterations;
      return;
    }
    // λ = λ_exp: a = B λ (the text's TransposeMultiply)
    if (pitfalls.has(Pitfall::lambda_b1)) {
      transpose_multiply_text_slip(rows, mlcp.body_count(), lambda, a_of_body);
    } else if (all_zero(lambda, mlcp.row_count())) {
      a_of_body.assign(static_cast<std::size_t>(mlcp.body_count()), Block<N>::Zero());
    } else {
      transpose_multiply(rows, mlcp.body_count(), lambda, a_of_body);
    }
    if (in_lanes) {
      if (clamp_increment) {
        sweep_in_lanes<N, true>(rows, mlcp.groups(), a_of_body.data(), lambda, 0, 1,
                                 settings.iterations);
      } else {
        sweep_in_lanes<N, false>(rows, mlcp.groups(), a_of_body.data(), lambda, 0, 1,
                                 settings.iterations);
      }
      result.iterations = settings.iterations;
      return;
    }
    for (int iter = 0; iter < settings.iterations; ++iter) {
      if (clamp_increment) {
        sweep<N, true>(rows, mlcp.groups(), a_of_body, lambda);
      } else {
        sweep<N, false>(rows, mlcp.groups(), a_of_body, lambda);
      }
      result.iterations = iter + 1;
      if (!measure) continue;
      const double r = mlcp.residual(lambda);
      if (settings.record_sweeps) {
        result.residuals.push_back(r);
        result.lambdas.push_back(Eigen::Map<const Eigen::VectorXd>(lambda, mlcp.row_count()));
      }
      if (settings.tolerance > 0.0 && r <= settings.tolerance) break;
    }
  });
}

Vec6 PgsSolver::velocity_change(int body) const {
  return planar_ ? widen(planar_a_[body]) : widen(general_a_[body]);
}

SweepResult solve_pgs(const Mlcp& mlcp, const Eigen::VectorXd& lambda_exp,
                      const SweepSettings& settings) {
  PgsSolver solver;
  SweepResult result;
  result.lambda = lambda_exp;
  solver.solve(mlcp, result.lambda.data(), settings, result);
  return result;
}

}  // namespace lamina
