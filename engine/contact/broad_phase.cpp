#include "contact/broad_phase.h"

#include <algorithm>
#include <numeric>

namespace lamina {

void sort_and_sweep(const std::vector<Aabb>& boxes, std::vector<int>& order,
                    std::vector<BodyPair>& pairs) {
  order.resize(boxes.size());
  std::iota(order.begin(), order.end(), 0);
  // 1. sort by min.x; equal edges keep index order
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return boxes[a].min.x() < boxes[b].min.x(); });
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
