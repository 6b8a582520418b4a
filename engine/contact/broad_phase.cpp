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

void sort_and_sweep(const std::vector<Aabb>& boxes, std::vector<int>& order,
                    std::vector<BodyPair>& pairs) {
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
  pairs.clear();
  for (size_t k = 0; k < order.size(); ++k) {
    const Aabb& box = boxes[order[k]];
    // 2. sweep: only the bodies starting left of this box's right edge can overlap it in x
    for (size_t l = k + 1; l < order.size() && boxes[order[l]].min.x() <= box.max.x(); ++l) {
      // 3. and they must overlap in y too
      if (!box.overlaps(boxes[order[l]])) continue;
      pairs.push_back({std::min(order[k], order[l]), std::max(order[k], order[l])});
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace lamina
