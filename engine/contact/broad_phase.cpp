#include "contact/broad_phase.h"

#include <algorithm>
#include <numeric>

namespace lamina {
namespace {

// Sorts a nearly sorted sequence in about one pass (last step's order, the bodies having moved
// a little since).
template <class Before>
void insertion_sort(std::vector<int>& order, const Before& before) {
  for (size_t k = 1; k < order.size(); ++k) {
    const int body = order[k];
    size_t l = k;
    for (; l > 0 && before(body, order[l - 1]); --l) order[l] = order[l - 1];
    order[l] = body;
  }
}

}  // namespace

void sort_and_sweep(const std::vector<Aabb>& boxes, SweepMemory& memory,
                    std::vector<BodyPair>& pairs) {
  std::vector<int>& order = memory.order;
  // 1. sort by min.x, equal edges in index order
  const auto before = [&](int a, int b) {
    return boxes[a].min.x() < boxes[b].min.x() || (boxes[a].min.x() == boxes[b].min.x() && a < b);
  };
  if (order.size() != boxes.size()) {
    order.resize(boxes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), before);
  } else {
    insertion_sort(order, before);
  }
  // the boxes in sweep order, side by side: a tall pile puts a whole column of boxes within each
  // box's x-interval, and the sweep reads them one after another
  std::vector<Aabb>& sorted = memory.sorted;
  sorted.resize(boxes.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = boxes[order[k]];
  std::vector<BodyPair>& found = memory.found;
  found.clear();
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    const Aabb& box = sorted[k];
    // 2. sweep: only the bodies starting left of this box's right edge can overlap it in x
    for (std::size_t l = k + 1; l < sorted.size() && sorted[l].min.x() <= box.max.x(); ++l) {
      // 3. and they must overlap in y too
      if (!box.overlaps(sorted[l])) continue;
      found.push_back({std::min(order[k], order[l]), std::max(order[k], order[l])});
    }
  }
  // 4. sorted by (first, second): counted into place by first body, then each body's few pairs
  // put in order by second
  std::vector<int>& start = memory.first_count;
  start.assign(boxes.size() + 1, 0);
  for (const BodyPair& pair : found) ++start[pair.first + 1];
  for (std::size_t b = 0; b < boxes.size(); ++b) start[b + 1] += start[b];
  pairs.resize(found.size());
  for (const BodyPair& pair : found) pairs[start[pair.first]++] = pair;
  for (std::size_t k = 1; k < pairs.size(); ++k) {
    const BodyPair pair = pairs[k];
    std::size_t l = k;
    for (; l > 0 && pair < pairs[l - 1]; --l) pairs[l] = pairs[l - 1];
    pairs[l] = pair;
  }
}

}  // namespace lamina
