#include "constraints/part_plan.h"

#include <algorithm>

namespace lamina {
namespace {

// For each cut between two parts, at most one group in max_wait_share may wait on another part
// (a pyramid of base 20 in 2 parts: one in 20); otherwise the parts would mostly wait on each
// other. Threads' parts (more than two, two a thread) hand each waited-for body from core to
// core; one thread's two lanes (two parts) only go one at a time while one waits, and are worth
// more waits: a honeycomb of 55 hexagons (hexagon-pyramid), about one group in five waiting,
// sweeps 17–20 % faster in lanes, while a pile of capsules (capsule-pile), more than one in four,
// sweeps 12 % slower (docs/performance.md).
constexpr int max_wait_share_threads = 8;
constexpr int max_wait_share_lanes = 4;

}  // namespace

bool PartPlan::serves(const Mlcp& mlcp, int parts) const {
  const std::vector<RowGroup>& groups = mlcp.groups();
  if (parts != parts_ || groups.size() != bodies_.size()) return false;
  const RowGroup* const group = groups.data();
  const std::array<int, 2>* const bodies = bodies_.data();
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (!same_bodies(group[g].bodies, bodies[g])) return false;
  }
  return true;
}

bool PartPlan::make(const Mlcp& mlcp, int parts) {
  const std::vector<RowGroup>& groups = mlcp.groups();
  const int group_count = static_cast<int>(groups.size()) - 1;
  const long rows = mlcp.row_count();
  bodies_.resize(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) bodies_[g] = groups[g].bodies;
  parts_ = parts;
  // the parts: consecutive groups, each part about its share of the rows; part t starts at the
  // first group whose first row r has min(parts − 1, r·parts/rows) ≥ t (r grows with g)
  const auto part_of_row = [&](long first) {
    return std::min<long>(parts - 1, first * parts / rows);
  };
  part_first_.resize(static_cast<std::size_t>(parts) + 1);
  for (int t = 0; t <= parts; ++t) {
    const auto starts = std::partition_point(
        groups.begin(), groups.begin() + group_count,
        [&](const RowGroup& group) { return part_of_row(group.first) < t; });
    part_first_[t] = static_cast<int>(starts - groups.begin());
  }
  // the part of group g, looked up only where a group's body was last met in another part
  const auto part_of = [&](int g) {
    return static_cast<int>(std::upper_bound(part_first_.begin(), part_first_.end(), g) -
                            part_first_.begin()) - 1;
  };
  // the waits: the group before g on each of its bodies, this pass's or the last of the pass
  // before, when another part takes it. Walked through raw pointers and locals: a store through
  // a vector's element could otherwise be taken to change the vectors the loop reads (reloading
  // them took a sixth of the plan's instructions: 37.3 M → 30.8 M in 20 steps of pyramid:80).
  last_group_of_body_.assign(static_cast<std::size_t>(mlcp.body_count()), -1);
  int* const last_group = last_group_of_body_.data();
  const RowGroup* const group = groups.data();
  for (int g = 0; g < group_count; ++g) {
    for (const int body : group[g].bodies) {
      if (body >= 0) last_group[body] = g - group_count;  // in the pass before
    }
  }
  // a wait kept only for a group that waits (few do: a table of every group's was cleared for
  // every plan, some 230 kB at base 80); room for one a group, so that a plan allocates no
  // more once the groups have stopped growing
  wait_index_.assign(static_cast<std::size_t>(group_count), -1);
  waits_.clear();
  waits_.reserve(static_cast<std::size_t>(group_count));
  waited_on_.assign(static_cast<std::size_t>(group_count), 0);
  int* const wait_index = wait_index_.data();
  unsigned char* const waited_on = waited_on_.data();
  long waits = 0;
  int part = 0;
  int part_begin = part_first_[0];
  int part_end = part_first_[1];
  for (int g = 0; g < group_count; ++g) {
    while (g >= part_end) {
      ++part;
      part_begin = part_end;
      part_end = part_first_[static_cast<std::size_t>(part) + 1];
    }
    for (int k = 0; k < 2; ++k) {
      const int body = group[g].bodies[k];
      if (body < 0) continue;
      const int before = last_group[body];
      last_group[body] = g;
      const int g_before = before < 0 ? before + group_count : before;
      if (g_before >= part_begin && g_before < part_end) continue;  // its own
      const int theirs = part_of(g_before);
      waited_on[g_before] = 1;
      ++waits;
      if (wait_index[g] < 0) {
        wait_index[g] = static_cast<int>(waits_.size());
        waits_.emplace_back();
      }
      GroupWait& wait = waits_[static_cast<std::size_t>(wait_index[g])];
      if (k == 1 && wait.part[0] == theirs) {
        wait.after[0] = std::max(wait.after[0], static_cast<long>(before) + 1);
      } else {
        wait.part[k] = theirs;
        wait.after[k] = static_cast<long>(before) + 1;
      }
    }
  }
  // the runs, from the last group back: a run from g ends after g when another part waits for g
  // or g + 1 waits itself, else where the run from g + 1 ends
  run_end_.resize(static_cast<std::size_t>(group_count));
  int* const run_end = run_end_.data();
  int end = group_count;  // where the run from the group after g ends
  for (int g = group_count - 1; g >= 0; --g) {
    const bool next_waits = g + 1 < group_count && wait_index[g + 1] >= 0;
    if (waited_on[g] != 0 || next_waits) end = g + 1;
    run_end[g] = end;
  }
  // rows whose bodies are spread over the whole order (bodies added in no spatial order) would
  // make the parts wait at every few groups: then one part is faster
  const int share = lanes_of_one_thread(parts) ? max_wait_share_lanes : max_wait_share_threads;
  usable_ = waits <= static_cast<long>(parts - 1) * group_count / share;
  return usable_;
}

}  // namespace lamina
