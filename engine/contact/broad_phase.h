// Broad phase: which pairs of bodies may touch, by sort and sweep on x within bands of y (beyond
// the text, which leaves collision detection to its references [9] and [10]; docs/the-text.md).
//
//   1. sort the bodies by the left edge min.x of their bounding boxes;
//   2. cut the plane into horizontal bands about two typical boxes high and list, band by band,
//      the boxes that reach into each (in x order: a box in two bands is listed in both);
//   3. sweep each band left to right: box i can only overlap the boxes after it whose
//      min.x ≤ max.x of i; of those, keep the ones whose boxes also overlap in y, in the one band
//      that holds the bottom of their overlap (so each pair is found once).
// The bands keep a tall pile from putting a whole column of boxes within each box's x-interval:
// a sweep on x alone checks about n·h candidates for a pile h boxes high, the bands a few per
// box. The pairs come out as (first < second), sorted by first then second, so the rows built
// from them, and so every result, do not depend on the bands, the threads or how the sort broke
// ties.
#pragma once

#include <array>
#include <vector>

#include "contact/shape.h"
#include "parallel/workers.h"

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
  std::vector<int> order;                 // body indices sorted by min.x as of the last call
  std::vector<double> heights;            // the boxes' heights, for their median (the bands')
  std::vector<int> band_start;            // per band, where its boxes begin in `banded`
  std::vector<std::array<int, 2>> reach;  // per box in x order, its first and last band
  PerRun<std::vector<int>> band_fill_of_run;  // per run, per band, where its next box goes
  std::vector<Aabb> banded;               // the boxes band after band, each band's in x order
  std::vector<int> banded_body;           // the body of each of them
  PerRun<std::vector<BodyPair>> found_of_run;  // per run of bands, the pairs it found
  PerRun<std::vector<int>> first_next_of_run;  // per run, per body, where its next pair goes
  std::vector<int> first_start;           // per body, where its pairs (it first) begin
};

// The pairs of overlapping (or touching) boxes, sorted. `memory.order` holds the body indices
// sorted by min.x: empty (or of another size) on the first call, then last call's order for the
// same bodies, which an insertion sort brings up to date in about one pass when bodies move a
// little between steps (sort and sweep's frame coherence). With `workers`, each of their threads
// lists the boxes of a run of the x order in their bands, sweeps a run of consecutive bands and
// puts its pairs in order with the others' (the same pairs, in the same order).
void sort_and_sweep(const std::vector<Aabb>& boxes, SweepMemory& memory,
                    std::vector<BodyPair>& pairs, Workers* workers = nullptr);

}  // namespace lamina
