// PGS's lanes (pgs_solver.h): a thread's parts of one MLCP, or of two swept side by side, taken
// two at a time as far as their waits allow, and the view of an MLCP they sweep.
#include "constraints/pgs_solver.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace lamina {
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

}  // namespace

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
    const PartPlan::GroupWait* const wait = m.plan->wait_of(l.next);
    if (wait == nullptr) return Wait::go;
    const Lane& other = lane[static_cast<std::size_t>(u ^ 1)];  // the same MLCP's other lane
    for (int e = 0; e < 2; ++e) {
      const int v = wait->part[e];
      if (v < 0) continue;
      const long needed = l.pass * m.group_count + wait->after[e];
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
  // In its MLCP's last sweep, when the MLCP adds F_c = Jᵀ λ (Swept::forces_to), the terms of
  // lane u's next n groups, just swept (their λ final, their rows at hand): before the lane's
  // count of groups passed moves on, so that a group after them on their bodies, which waits
  // for that count, comes after them in each body's sum as it does in a_b's.
  const auto add_forces = [&](int u, int n) {
    const Lane& l = lane[static_cast<std::size_t>(u)];
    const Swept<N>& m = *l.m;
    if (m.forces_to == nullptr || l.pass != m.sweeps) return;
    for (int g = l.next; g < l.next + n; ++g) {
      // eq. 3-11
      add_group_forces(m.rows, m.lambda, m.groups[g].first, m.groups[g + 1].first, m.forces_to);
    }
  };
  const auto take = [&](int u, int n) {  // lane u's next n groups, alone
    const Lane& l = lane[static_cast<std::size_t>(u)];
    const Swept<N>& m = *l.m;
    for (int g = l.next; g < l.next + n; ++g) {
      if (l.pass == 0) {
        pass_group<N, ClampIncrement, GroupPass::transpose>(m.rows, m.groups[g].first,
                                                       m.groups[g + 1].first, m.a, m.lambda);
      } else {
        pass_group<N, ClampIncrement, GroupPass::sweep>(m.rows, m.groups[g].first,
                                                   m.groups[g + 1].first, m.a, m.lambda);
      }
    }
    add_forces(u, n);
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
      add_forces(go[0], n);
      add_forces(go[1], n);
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

// The lanes PgsSolver's solves take (pgs_solver.cpp): both layouts, with and without the pitfall
// clamp-increment.
template void PgsSolver::sweep_in_lanes<3, false>(const Swept<3>*, int, int) const;
template void PgsSolver::sweep_in_lanes<3, true>(const Swept<3>*, int, int) const;
template void PgsSolver::sweep_in_lanes<6, false>(const Swept<6>*, int, int) const;
template void PgsSolver::sweep_in_lanes<6, true>(const Swept<6>*, int, int) const;
template PgsSolver::Swept<3> PgsSolver::swept(const Mlcp&, const PackedRows<3>&,
                                              std::vector<Block<3>>&, double*, int, int) const;
template PgsSolver::Swept<6> PgsSolver::swept(const Mlcp&, const PackedRows<6>&,
                                              std::vector<Block<6>>&, double*, int, int) const;

}  // namespace lamina
