#include "constraints/pgs_solver.h"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

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

}  // namespace

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
};

namespace {

// One pass over two groups at once, of different lanes and on different bodies (of one MLCP, or
// of two swept side by side): row j of the first group, then row j of the second, each the
// arithmetic of pgs_row on its own group's a_b, so that the two chains of arithmetic overlap (a
// group has one to three rows).
template <int N, bool ClampIncrement, class Swept>
[[gnu::always_inline]] inline void pass_two_groups(const Swept& p, int first, const Swept& q,
                                                   int second) {
  const PackedRow<N>* const p_rows = p.rows;
  const PackedRow<N>* const q_rows = q.rows;
  const int b1 = p_rows[p.groups[first].first].map[0];
  const int b2 = p_rows[p.groups[first].first].map[1];
  const int c1 = q_rows[q.groups[second].first].map[0];
  const int c2 = q_rows[q.groups[second].first].map[1];
  Block<N> a1 = p.a[b1];
  Block<N> a2 = b2 >= 0 ? p.a[b2] : Block<N>::Zero();
  Block<N> e1 = q.a[c1];
  Block<N> e2 = c2 >= 0 ? q.a[c2] : Block<N>::Zero();
  int i = p.groups[first].first;
  int j = q.groups[second].first;
  const int i_end = p.groups[first + 1].first;
  const int j_end = q.groups[second + 1].first;
  double* const p_lambda = p.lambda;
  double* const q_lambda = q.lambda;
  for (; i < i_end && j < j_end; ++i, ++j) {
    pgs_row<N, ClampIncrement>(p_rows[i], static_cast<std::size_t>(i), p_lambda, a1, a2);
    pgs_row<N, ClampIncrement>(q_rows[j], static_cast<std::size_t>(j), q_lambda, e1, e2);
  }
  for (; i < i_end; ++i) {
    pgs_row<N, ClampIncrement>(p_rows[i], static_cast<std::size_t>(i), p_lambda, a1, a2);
  }
  for (; j < j_end; ++j) {
    pgs_row<N, ClampIncrement>(q_rows[j], static_cast<std::size_t>(j), q_lambda, e1, e2);
  }
  p.a[b1] = a1;
  if (b2 >= 0) p.a[b2] = a2;
  q.a[c1] = e1;
  if (c2 >= 0) q.a[c2] = e2;
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
template <>
std::vector<Block<3>>& PgsSolver::first_a_of<3>() { return first_planar_a_; }
template <>
std::vector<Block<6>>& PgsSolver::first_a_of<6>() { return first_general_a_; }

void PgsSolver::use_workers(Workers* workers) {
  if (workers == nullptr || workers->count() < 2) workers = nullptr;
  if (workers == workers_) return;
  workers_ = workers;
  // per part of each of two MLCPs (solve_both)
  progress_.reset(workers_ != nullptr ? new Progress[2 * runs_on(workers_)] : nullptr);
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

// Thread t's lanes of `count` MLCPs (one, or two side by side): of each, parts t and P − 1 − t
// of its plan's P parts (from both ends of the wavefront: pgs_solver.h), each lane taking
// passes `first_pass` to `sweeps` over its part's groups (pass 0 is a = B λ, passes 1, 2, … the
// sweeps). Each lane goes as far as its waits allow: on the thread's other lane of the same
// MLCP, through the lanes' own counts of groups passed; on another thread's part, through that
// part's Progress. A lane's wait is looked at only where a run of its groups starts
// (PartPlan::run_end: a group that waits starts a run, and a run ends after a group that
// another part waits for); the groups after the first of a run wait on no other part. Each step
// takes the next run of the first two lanes that may go, the first MLCP's lanes first — both
// side by side as far as the shorter goes where two can (pass_two_groups), else the one alone.
// Each lane starts once the groups its first groups share bodies with have been passed (about a
// pass of the part before it); the second MLCP's lanes fill the time the first's wait. Some lane
// can always go, or will once another thread has got further: of each MLCP, the first of all
// the parts' next groups in the one-thread order has every group before it on its bodies behind
// it.
template <int N, bool ClampIncrement>
[[gnu::flatten]] void PgsSolver::sweep_in_lanes(const Swept<N>* swept, int count, int t) const {
  // a lane: its MLCP and part, its part's groups [begin, end), its next pass and group, and its
  // count k·G + g + 1 of the last group passed (when the first pass is a sweep, pass 0 was done
  // before); an empty lane is done
  struct Lane {
    const Swept<N>* m;
    int part;
    int begin;
    int end;
    long pass;
    int next;
    long passed;
  };
  std::array<Lane, 4> lane{};
  const int lanes = 2 * count;
  for (int s = 0; s < count; ++s) {
    const Swept<N>& m = swept[s];
    const std::array<int, 2> part = runs_of_thread(t, m.plan->parts());
    for (int k = 0; k < 2; ++k) {
      Lane& l = lane[static_cast<std::size_t>(2 * s + k)];
      l.m = &m;
      l.part = part[k];
      l.begin = m.plan->first_group(part[k]);
      l.end = m.plan->first_group(part[k] + 1);
      l.pass = l.begin == l.end ? m.sweeps + 1 : m.first_pass;
      l.next = l.begin;
      l.passed = (m.first_pass - 1) * m.group_count + l.end;
    }
  }
  // the last count read from each other part of each MLCP (a run each)
  std::array<std::array<long, max_runs>, 2> seen{};
  // what lane u's next group waits on: nothing (go), this thread's other lane of its MLCP, or
  // another thread's part; or the lane is done
  enum class Wait { go, own_lane, other_thread, done };
  const auto waits_for = [&](int u) {
    const Lane& l = lane[static_cast<std::size_t>(u)];
    const Swept<N>& m = *l.m;
    if (l.pass > m.sweeps) return Wait::done;
    const PartPlan::GroupWait& wait = m.plan->waits()[l.next];
    const Lane& other = lane[static_cast<std::size_t>(u ^ 1)];  // the same MLCP's other lane
    for (int e = 0; e < 2; ++e) {
      const int v = wait.part[e];
      if (v < 0) continue;
      const long needed = l.pass * m.group_count + wait.after[e];
      if (v == other.part) {
        if (other.passed < needed) return Wait::own_lane;
      } else {
        long& seen_v = seen[static_cast<std::size_t>(u / 2)][static_cast<std::size_t>(v)];
        if (seen_v < needed) {
          seen_v = m.progress[v].value();
          if (seen_v < needed) return Wait::other_thread;
        }
      }
    }
    return Wait::go;
  };
  // lane u's next run of groups (PartPlan::run_end), cut at its part's end: the first may wait,
  // the others need not be looked at
  const auto run_length = [&](int u) {
    const Lane& l = lane[static_cast<std::size_t>(u)];
    return std::min(l.m->plan->run_end(l.next), l.end) - l.next;
  };
  const auto take = [&](int u, int n) {  // lane u's next n groups, alone
    const Lane& l = lane[static_cast<std::size_t>(u)];
    const Swept<N>& m = *l.m;
    for (int g = l.next; g < l.next + n; ++g) {
      if (l.pass == 0) {
        pass_group<N, ClampIncrement, Pass::transpose>(m.rows, m.groups[g].first,
                                                       m.groups[g + 1].first, m.a, m.lambda);
      } else {
        pass_group<N, ClampIncrement, Pass::sweep>(m.rows, m.groups[g].first,
                                                   m.groups[g + 1].first, m.a, m.lambda);
      }
    }
  };
  const auto advance = [&](int u, int n) {  // lane u has passed its next n groups
    Lane& l = lane[static_cast<std::size_t>(u)];
    const Swept<N>& m = *l.m;
    l.next += n;
    l.passed = l.pass * m.group_count + l.next;
    if (m.progress != nullptr && m.plan->waited_on(l.next - 1)) {
      m.progress[l.part].publish(l.passed);  // only its last group may be waited for
    }
    if (l.next == l.end) {
      l.next = l.begin;
      ++l.pass;
    }
  };
  int waiting_turns = 0;  // looks in a row at lanes that all wait
  for (;;) {
    std::array<int, 2> go{};
    int found = 0;
    bool left = false;         // a lane not done
    bool on_other = false;     // a lane that waits on another thread's part
    for (int u = 0; u < lanes && found < 2; ++u) {
      const Wait wait = waits_for(u);
      if (wait == Wait::done) continue;
      left = true;
      if (wait == Wait::go) go[static_cast<std::size_t>(found++)] = u;
      if (wait == Wait::other_thread) on_other = true;
    }
    if (!left) return;
    if (found == 2 && lane[go[0]].pass > 0 && lane[go[1]].pass > 0) {
      // the two runs side by side, as far as the shorter goes
      const Lane& l0 = lane[static_cast<std::size_t>(go[0])];
      const Lane& l1 = lane[static_cast<std::size_t>(go[1])];
      const int n = std::min(run_length(go[0]), run_length(go[1]));
      if (l0.m == l1.m) {  // one MLCP's two lanes: its arrays read once for both (fewer registers)
        const Swept<N>& m = *l0.m;
        for (int k = 0; k < n; ++k) {
          pass_two_groups<N, ClampIncrement>(m, l0.next + k, m, l1.next + k);
        }
      } else {
        for (int k = 0; k < n; ++k) {
          pass_two_groups<N, ClampIncrement>(*l0.m, l0.next + k, *l1.m, l1.next + k);
        }
      }
      advance(go[0], n);
      advance(go[1], n);
    } else if (found > 0) {
      for (int k = 0; k < found; ++k) {
        const int n = run_length(go[static_cast<std::size_t>(k)]);
        take(go[static_cast<std::size_t>(k)], n);
        advance(go[static_cast<std::size_t>(k)], n);
      }
    } else {
      // every lane waits, one at least on another thread's part (else the plan is wrong): look
      // at them all again after a moment. Not waiting on that part alone: it may be waiting, in
      // turn, on one of this thread's lanes, which is free to go once its own wait is over.
      if (!on_other || swept[0].progress == nullptr) {
        throw std::logic_error("PGS's lanes all wait on each other: their plan is wrong");
      }
      workers_->wait_a_turn(waiting_turns);
      continue;
    }
    waiting_turns = 0;
  }
}

template <int N>
PgsSolver::Swept<N> PgsSolver::swept(const Mlcp& mlcp, const PackedRows<N>& rows,
                                     std::vector<Block<N>>& a_of_body, double* lambda, int sweeps,
                                     int index) const {
  Swept<N> m;
  m.rows = rows.data();
  m.groups = mlcp.groups().data();
  m.group_count = static_cast<long>(mlcp.groups().size()) - 1;
  m.a = a_of_body.data();
  m.lambda = lambda;
  m.plan = plan_;
  m.progress = workers_ != nullptr ? progress_.get() + index * runs_on(workers_) : nullptr;
  m.sweeps = sweeps;
  return m;
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
      a_of_body.assign(static_cast<std::size_t>(mlcp.body_count()), Block<N>::Zero());
      Swept<N> m = swept(mlcp, rows, a_of_body, lambda, settings.iterations, 0);
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
      const Swept<N> m = swept(mlcp, rows, a_of_body, lambda, settings.iterations, 0);
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
}

void PgsSolver::solve_both(const Mlcp& first, double* first_lambda,
                           const SweepSettings& first_settings, SweepResult& first_result,
                           const Mlcp& second, double* second_lambda,
                           const SweepSettings& second_settings, SweepResult& second_result,
                           Pitfalls pitfalls) {
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
    solve(first, first_lambda, first_settings, first_result, pitfalls);
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
