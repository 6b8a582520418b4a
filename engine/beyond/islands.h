// Islands (beyond the text): the rows of a step's MLCP split into groups that share no moving
// body. Two rows are in one island when a chain of rows joins their bodies; a static body joins
// nothing (it holds no block in any row, jacobian_rows.h). The MLCP of eq. 3-24 then splits into
// one MLCP per island, each solvable on its own and by a method of its own: J B is block
// diagonal over the islands, and a friction row's bounds read only its own contact rows, which
// are in its island.
//
// Box2D's islands serve sleeping and parallelism; here they let a method pick a solve per island
// (island_method.h). Found by union-find over the rows' bodies (Tarjan 1975), in row order, so
// the same rows give the same islands, numbered by their first row.
#pragma once

#include <cstddef>
#include <vector>

#include "constraints/mlcp.h"

namespace lamina {

// The largest island solved exactly: its LCP's variables (Island::lcp_size). Lemke's pivots cost
// the square of the variables each and take about as many pivots as variables; 240 is a stack of
// 30 boxes with friction (two points each, 8 variables a box), about 1.6 ms a step.
constexpr int exact_island_limit = 240;

struct Island {
  std::vector<int> rows;    // its rows, ascending
  std::vector<int> bodies;  // the moving bodies they touch, ascending
  int joint_rows = 0;       // how many of its rows are joints' (at or after first_joint_row)
  // The variables of its exact solve (exact_mlcp.h): 1 per one-sided row, 2 per equality row,
  // 3 per friction row; counted only while at most exact_island_limit (an island past it is
  // swept by PGS whatever its size), so that a pile's rows are not all read to count them: past
  // the limit it stops at the first group of rows that takes it past.
  int lcp_size = 0;
};

// The islands of the MLCP's rows, ordered by their first row. Rows from first_joint_row on are
// joints' rows.
std::vector<Island> find_islands(const Mlcp& mlcp, std::size_t first_joint_row);

// The same islands found in memory kept from step to step: a steady step finds its islands
// without allocating (a method's member, found again every step).
class IslandList {
 public:
  // Finds the islands of the MLCP's rows, as find_islands, in place of the last ones.
  void find(const Mlcp& mlcp, std::size_t first_joint_row);
  const Island* begin() const { return islands_.data(); }
  const Island* end() const { return islands_.data() + count_; }
  std::size_t size() const { return count_; }

 private:
  std::vector<Island> islands_;  // the first count_ are the islands found; the rest keep their memory
  std::size_t count_ = 0;
  std::vector<int> parent_;      // union-find's parent of each body
  std::vector<int> island_of_root_;
  std::vector<int> island_of_group_;  // each group's island
  std::vector<int> row_count_;        // each island's rows, counted, then written
  std::vector<unsigned char> seen_;   // the bodies some row touches
};

}  // namespace lamina
