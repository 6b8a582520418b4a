#include "beyond/islands.h"

#include <algorithm>
#include <array>
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
  for (std::size_t g = 0; g < group_count; ++g) {
    const std::array<int, 2>& b = groups[g].bodies;
    if (b[1] < 0) continue;
    const int r0 = root_of(parent_, b[0]);
    const int r1 = root_of(parent_, b[1]);
    // the smaller root stays: the same rows join the same way whatever the order of unions
    if (r0 != r1) parent_[static_cast<std::size_t>(std::max(r0, r1))] = std::min(r0, r1);
  }
  count_ = 0;
  island_of_root_.assign(parent_.size(), -1);
  seen_.assign(parent_.size(), 0);
  mlcp.visit([&](const auto& rows) {
    for (std::size_t g = 0; g < group_count; ++g) {
      const std::array<int, 2>& b = groups[g].bodies;
      const std::size_t root = static_cast<std::size_t>(root_of(parent_, b[0]));
      if (island_of_root_[root] < 0) {
        island_of_root_[root] = static_cast<int>(count_);
        if (count_ == islands_.size()) islands_.emplace_back();
        Island& fresh = islands_[count_++];
        fresh.rows.clear();  // memory of an earlier step's island kept
        fresh.bodies.clear();
        fresh.joint_rows = 0;
        fresh.lcp_size = 0;
      }
      Island& island = islands_[static_cast<std::size_t>(island_of_root_[root])];
      for (int i = groups[g].first; i < groups[g + 1].first; ++i) {
        island.rows.push_back(i);
        if (static_cast<std::size_t>(i) >= first_joint_row) ++island.joint_rows;
        island.lcp_size += lcp_variables(rows[static_cast<std::size_t>(i)]);
      }
      for (const int body : b) {
        if (body < 0 || seen_[static_cast<std::size_t>(body)]) continue;
        seen_[static_cast<std::size_t>(body)] = 1;
        island.bodies.push_back(body);
      }
    }
  });
  for (std::size_t k = 0; k < count_; ++k) std::sort(islands_[k].bodies.begin(), islands_[k].bodies.end());
}

}  // namespace lamina
