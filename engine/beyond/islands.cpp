#include "beyond/islands.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <numeric>

namespace lamina {
namespace {

// Union-find's root of body b, halving the path on the way.
int root_of(std::vector<int>& parent, int b) {
  while (parent[static_cast<std::size_t>(b)] != b) {
    int& p = parent[static_cast<std::size_t>(b)];
    p = parent[static_cast<std::size_t>(p)];
    b = p;
  }
  return b;
}

// The variables of a row in the LCP of exact_mlcp.h.
template <class Row>
int lcp_variables(const Row& row) {
  if (row.friction_of >= 0) return 3;  // p, m and the slip speed s
  const double none = 0.0;
  const std::array<double, 2> b = bounds_of(row, &none);
  return std::isinf(b[0]) ? 2 : 1;  // λ = p − m, or λ itself
}

}  // namespace

std::vector<Island> find_islands(const Mlcp& mlcp, std::size_t first_joint_row) {
  IslandList list;
  list.find(mlcp, first_joint_row);
  return std::vector<Island>(list.begin(), list.end());
}

void IslandList::find(const Mlcp& mlcp, std::size_t first_joint_row) {
  // The rows of a group (Mlcp::groups) share their bodies, so the unions are made group by group.
  const std::vector<RowGroup>& groups = mlcp.groups();
  const std::size_t group_count = groups.empty() ? 0 : groups.size() - 1;  // the last is the end
  parent_.resize(static_cast<std::size_t>(mlcp.body_count()));
  std::iota(parent_.begin(), parent_.end(), 0);
  seen_.assign(parent_.size(), 0);  // the bodies some row touches
  for (std::size_t g = 0; g < group_count; ++g) {
    const std::array<int, 2>& b = groups[g].bodies;
    seen_[static_cast<std::size_t>(b[0])] = 1;
    if (b[1] < 0) continue;
    seen_[static_cast<std::size_t>(b[1])] = 1;
    const int r0 = root_of(parent_, b[0]);
    const int r1 = root_of(parent_, b[1]);
    // the smaller root stays: the same rows join the same way whatever the order of unions
    if (r0 != r1) parent_[static_cast<std::size_t>(std::max(r0, r1))] = std::min(r0, r1);
  }
  // every body's root at once: a root is the smallest body of its tree, so each body's parent
  // is below it, and in ascending order its parent's root is known when the body is reached
  for (std::size_t b = 0; b < parent_.size(); ++b) {
    parent_[b] = parent_[static_cast<std::size_t>(parent_[b])];
  }
  count_ = 0;
  island_of_root_.assign(parent_.size(), -1);
  island_of_group_.resize(group_count);
  row_count_.clear();
  const int joint_from = static_cast<int>(std::min<std::size_t>(first_joint_row, INT_MAX));
  mlcp.visit([&](const auto& rows) {
    for (std::size_t g = 0; g < group_count; ++g) {
      const std::size_t root =
          static_cast<std::size_t>(parent_[static_cast<std::size_t>(groups[g].bodies[0])]);
      if (island_of_root_[root] < 0) {
        island_of_root_[root] = static_cast<int>(count_);
        if (count_ == islands_.size()) islands_.emplace_back();
        Island& fresh = islands_[count_++];
        fresh.bodies.clear();  // memory of an earlier step's island kept
        fresh.joint_rows = 0;
        fresh.lcp_size = 0;
        row_count_.push_back(0);
      }
      const int k = island_of_root_[root];
      island_of_group_[g] = k;
      Island& island = islands_[static_cast<std::size_t>(k)];
      const int first = groups[g].first;
      const int last = groups[g + 1].first;
      row_count_[static_cast<std::size_t>(k)] += last - first;
      island.joint_rows += std::max(0, last - std::max(first, joint_from));
      if (island.lcp_size > exact_island_limit) continue;  // counted far enough (Island)
      for (int i = first; i < last; ++i) {
        island.lcp_size += lcp_variables(rows[static_cast<std::size_t>(i)]);
      }
    }
  });
  // each island's rows, ascending: its groups' rows in their order, written in place
  for (std::size_t k = 0; k < count_; ++k) {
    islands_[k].rows.resize(static_cast<std::size_t>(row_count_[k]));
    row_count_[k] = 0;  // now how many are written
  }
  for (std::size_t g = 0; g < group_count;) {
    // the run of groups from g in the same island (a pile's: all of them), its rows at once
    const int k = island_of_group_[g];
    std::size_t end = g + 1;
    while (end < group_count && island_of_group_[end] == k) ++end;
    const int first = groups[g].first;
    const int last = groups[end].first;
    int* const out =
        islands_[static_cast<std::size_t>(k)].rows.data() + row_count_[static_cast<std::size_t>(k)];
    std::iota(out, out + (last - first), first);
    row_count_[static_cast<std::size_t>(k)] += last - first;
    g = end;
  }
  // each island's bodies, ascending: the bodies its rows touch, found by their roots
  for (std::size_t b = 0; b < seen_.size(); ++b) {
    if (seen_[b] == 0) continue;
    const std::size_t root = static_cast<std::size_t>(parent_[b]);
    islands_[static_cast<std::size_t>(island_of_root_[root])].bodies.push_back(static_cast<int>(b));
  }
}

}  // namespace lamina
