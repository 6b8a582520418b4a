#include "constraints/pgs_solver.h"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

namespace lamina {
namespace {


// Whether λ is zero in every row (split impulse's position solve starts there): then a = B λ is
// zero without reading a row (each row's term would be skipped: add_row_term), and on threads
// the pass that makes it is skipped too.
bool all_zero(const double* lambda, int count) {
  return std::all_of(lambda, lambda + count, [](double l) { return l == 0.0; });
}

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
template <>
std::vector<Block<3>>& PgsSolver::first_a_of<3>() { return first_planar_a_; }
template <>
std::vector<Block<6>>& PgsSolver::first_a_of<6>() { return first_general_a_; }

void PgsSolver::use_workers(Workers* workers) {
  if (workers == nullptr || workers->count() < 2) workers = nullptr;
  if (workers == workers_) return;
  workers_ = workers;
  // the counters kept when a World's steps go to one thread and back (WorldSettings::
  // threads_min_bodies): made anew only for a larger team
  const int count = workers_ != nullptr ? 2 * runs_on(workers_) : 0;
  if (count > progress_count_) {
    progress_.reset(new Progress[count]);
    progress_count_ = count;
  }
}

bool PgsSolver::plan_parts(const Mlcp& mlcp, int parts) {
  const int min_rows = lanes_of_one_thread(parts) ? lanes_min_rows : threads_min_rows;
  if (mlcp.row_count() < min_rows || !mlcp.friction_on_own_bodies()) return false;
  // a plan kept for the MLCPs solved before, if one serves, the last used first (a step's
  // position MLCP is served by its velocity MLCP's plan, just made or used), else a new one in
  // place of the older
  PartPlan& last = plan_ == &plans_[1] ? plans_[1] : plans_[0];
  PartPlan& older = &last == &plans_[0] ? plans_[1] : plans_[0];
  for (PartPlan* plan : {&last, &older}) {
    if (!plan->serves(mlcp, parts)) continue;
    plan_ = plan;
    return plan->usable();
  }
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
    pass_group<N, ClampIncrement, GroupPass::sweep>(rows.data(), group[g].first, group[g + 1].first,
                                               a_of_body.data(), lambda);
  }
}

// On the workers' threads: for each MLCP, a = B λ (pass 0), then its sweeps (passes 1, 2, …),
// thread t taking parts t and 2T − 1 − t of each as lanes (sweep_in_lanes), pass after pass,
// and waiting where plan_parts found a group of another thread's part before one of its own.
// Each part starts pass k once the part before it has passed the rows its first rows share
// bodies with: a wavefront, each part at most a pass behind the one before it. Each MLCP's a
// must be sized and zero.
template <int N, bool ClampIncrement>
void PgsSolver::solve_on_threads(Swept<N>* swept, int count) {
  for (int s = 0; s < count; ++s) {
    Swept<N>& m = swept[s];
    // From λ = 0 a = B λ is the zero it starts as: pass 0 would add no term, so it is skipped,
    // and with it the pass of the wavefront that the parts spent waiting on each other in it.
    // Every part then starts as if it had passed its groups in pass 0 (the waits read those
    // counts).
    const int rows = m.groups[m.group_count].first;
    const bool from_zero = all_zero(m.lambda, rows);
    m.first_pass = from_zero ? 1 : 0;
    for (int p = 0; p < m.plan->parts(); ++p) {
      m.progress[p].reset(from_zero ? m.plan->first_group(p + 1) : 0);
    }
  }
  workers_->run([&](int t) { sweep_in_lanes<N, ClampIncrement>(swept, count, t); });
}

void PgsSolver::solve(const Mlcp& mlcp, double* lambda, const SweepSettings& settings,
                      SweepResult& result, Pitfalls pitfalls, std::vector<RigidBody>* forces_to) {
  const bool measure = settings.record_sweeps || settings.tolerance > 0.0;
  const bool plain = measure || pitfalls.has(Pitfall::lambda_b1);
  const bool threaded = workers_ != nullptr && !plain && plan_parts(mlcp, runs_on(workers_));
  const bool in_lanes = !threaded && !plain && settings.iterations >= 2 && plan_parts(mlcp, 2);
  const bool clamp_increment = pitfalls.has(Pitfall::clamp_increment);
  swept_on_threads_ = threaded;
  swept_in_lanes_ = in_lanes;
  // F_c in the last sweep of the parts (a solve of no sweep adds it after)
  RigidBody* const forces_in_sweep =
      (threaded || in_lanes) && forces_to != nullptr && settings.iterations >= 1
          ? forces_to->data()
          : nullptr;
  mlcp.visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    planar_ = N == 3;
    std::vector<Block<N>>& a_of_body = a<N>();
    if (threaded) {
      a_of_body.assign(static_cast<std::size_t>(mlcp.body_count()), Block<N>::Zero());
      Swept<N> m = swept(mlcp, rows, a_of_body, lambda, settings.iterations, 0);
      m.forces_to = forces_in_sweep;
      if (clamp_increment) {
        solve_on_threads<N, true>(&m, 1);
      } else {
        solve_on_threads<N, false>(&m, 1);
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
      Swept<N> m = swept(mlcp, rows, a_of_body, lambda, settings.iterations, 0);
      m.forces_to = forces_in_sweep;
      if (clamp_increment) {
        sweep_in_lanes<N, true>(&m, 1, 0);
      } else {
        sweep_in_lanes<N, false>(&m, 1, 0);
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
  // eq. 3-11: F_c = Jᵀ λ, where the sweeps did not add it
  if (forces_to != nullptr && forces_in_sweep == nullptr) {
    mlcp.add_constraint_forces(*forces_to, lambda, workers_);
  }
}

void PgsSolver::solve_both(const Mlcp& first, double* first_lambda,
                           const SweepSettings& first_settings, SweepResult& first_result,
                           const Mlcp& second, double* second_lambda,
                           const SweepSettings& second_settings, SweepResult& second_result,
                           Pitfalls pitfalls, std::vector<RigidBody>* forces_to) {
  const auto plain = [&](const SweepSettings& settings) {
    return settings.record_sweeps || settings.tolerance > 0.0 || settings.iterations < 2;
  };
  // side by side when each would be swept in parts by the same count of parts (each MLCP's
  // plan kept: a second plan made goes in the other place)
  const int parts = workers_ != nullptr ? runs_on(workers_) : 2;
  const PartPlan* first_plan = nullptr;
  bool side_by_side = !plain(first_settings) && !plain(second_settings) &&
                      !pitfalls.has(Pitfall::lambda_b1) && plan_parts(first, parts);
  if (side_by_side) {
    first_plan = plan_;
    side_by_side = plan_parts(second, parts);
  }
  swept_side_by_side_ = false;
  first.visit([&](const auto& first_rows) {
    second.visit([&](const auto& second_rows) {
      using FirstRows = std::decay_t<decltype(first_rows)>;
      if constexpr (std::is_same_v<FirstRows, std::decay_t<decltype(second_rows)>>) {
        if (!side_by_side) return;
        constexpr int N = FirstRows::value_type::size;
        const bool clamp_increment = pitfalls.has(Pitfall::clamp_increment);
        std::vector<Block<N>>& second_a = a<N>();
        std::vector<Block<N>>& first_a = first_a_of<N>();
        std::array<Swept<N>, 2> m;
        first_a.assign(static_cast<std::size_t>(first.body_count()), Block<N>::Zero());
        second_a.assign(static_cast<std::size_t>(second.body_count()), Block<N>::Zero());
        m[1] = swept(second, second_rows, second_a, second_lambda, second_settings.iterations, 1);
        plan_ = first_plan;
        m[0] = swept(first, first_rows, first_a, first_lambda, first_settings.iterations, 0);
        m[0].forces_to = forces_to != nullptr ? forces_to->data() : nullptr;  // ≥ 2 sweeps
        if (workers_ != nullptr) {
          if (clamp_increment) {
            solve_on_threads<N, true>(m.data(), 2);
          } else {
            solve_on_threads<N, false>(m.data(), 2);
          }
        } else {
          // one thread: a = B λ made before the lanes, as solve() makes it
          for (int s = 0; s < 2; ++s) {
            const Mlcp& mlcp = s == 0 ? first : second;
            std::vector<Block<N>>& a_of_body = s == 0 ? first_a : second_a;
            if (!all_zero(m[s].lambda, mlcp.row_count())) {
              transpose_multiply(s == 0 ? first_rows : second_rows, mlcp.body_count(),
                                 m[s].lambda, a_of_body);
            }
          }
          if (clamp_increment) {
            sweep_in_lanes<N, true>(m.data(), 2, 0);
          } else {
            sweep_in_lanes<N, false>(m.data(), 2, 0);
          }
        }
        planar_ = N == 3;
        swept_side_by_side_ = true;
      }
    });
  });
  if (!swept_side_by_side_) {
    solve(first, first_lambda, first_settings, first_result, pitfalls, forces_to);
    solve(second, second_lambda, second_settings, second_result, pitfalls);
    return;
  }
  swept_on_threads_ = workers_ != nullptr;
  swept_in_lanes_ = workers_ == nullptr;
  first_result.iterations = first_settings.iterations;
  second_result.iterations = second_settings.iterations;
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
