// Broad phase: which pairs of bodies may touch, by sort and sweep on x (beyond the text, which
// leaves collision detection to its references [9] and [10]; docs/the-text.md).
//
//   1. sort the bodies by the left edge min.x of their bounding boxes;
//   2. sweep left to right: body i can only overlap the bodies after it whose min.x ≤ max.x of i;
//   3. of those, keep the ones whose boxes also overlap in y.
// The pairs come out as (first < second), sorted by first then second, so the rows built from
// them, and so every result, do not depend on how the sort broke ties.
#pragma once

#include <vector>

#include "contact/shape.h"

namespace lamina {

// Two bodies that may touch, by index into the world's bodies; first < second.
struct BodyPair {
  int first = 0;   // the lower body index: "body 1" of eq. 4-1
  int second = 0;  // the higher body index: "body 2" of eq. 4-1

  bool operator<(const BodyPair& o) const {
    return first < o.first || (first == o.first && second < o.second);
  }
  bool operator==(const BodyPair& o) const { return first == o.first && second == o.second; }
};

// What the broad phase keeps from call to call: the bodies' order by min.x, which the next call
// starts its sort from, and room for its working copies, so that a step allocates nothing.
struct SweepMemory {
  std::vector<int> order;        // body indices sorted by min.x as of the last call
  std::vector<Aabb> sorted;      // their boxes in that order, side by side for the sweep
  std::vector<BodyPair> found;   // the pairs in the order the sweep meets them
  std::vector<int> first_count;  // per body, how many pairs have it first (the pairs' sort)
};

// The pairs of overlapping (or touching) boxes, sorted. `memory.order` holds the body indices
// sorted by min.x: empty (or of another size) on the first call, then last call's order for the
// same bodies, which an insertion sort brings up to date in about one pass when bodies move a
// little between steps (sort and sweep's frame coherence).
void sort_and_sweep(const std::vector<Aabb>& boxes, SweepMemory& memory,
                    std::vector<BodyPair>& pairs);

}  // namespace lamina
