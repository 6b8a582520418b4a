#include "contact/broad_phase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "parallel/workers.h"

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

// The runs' counts per item (`of_run[t][i]`: how many places run t fills for item i) turned
// into places: item i's begin at start[i], start[items] is the total, and within an item's the
// runs' follow in order, `of_run[t][i]` becoming where run t's first goes. Listed item by item
// and run by run, the places keep the order of one run after another.
void places_by_item(PerRun<std::vector<int>>& of_run, int runs, std::size_t items,
                    std::vector<int>& start) {
  start.resize(items + 1);
  int at = 0;
  for (std::size_t i = 0; i < items; ++i) {
    start[i] = at;
    for (int t = 0; t < runs; ++t) {
      const int count = of_run[t][i];
      of_run[t][i] = at;
      at += count;
    }
  }
  start[items] = at;
}

// Horizontal bands of one height from the lowest box up. `of` never decreases as y grows, so a
// box lies in the bands of(min.y) … of(max.y), and a height y within two boxes lies in a band
// both of them are listed in.
struct Bands {
  double bottom = 0.0;
  double height = 1.0;
  int count = 1;

  int of(double y) const {
    const double t = (y - bottom) / height;
    if (!(t > 0.0)) return 0;  // below the bottom, or not a number
    if (t >= count - 1) return count - 1;
    return static_cast<int>(t);
  }
};

// Bands twice the median box's height, so that a typical box lies in one or two of them; never
// more bands than boxes (a box far above the rest then widens them rather than adding empty
// ones). One band when the heights are not finite numbers.
Bands choose_bands(const std::vector<Aabb>& boxes, std::vector<double>& heights) {
  Bands bands;
  if (boxes.empty()) return bands;
  double bottom = boxes[0].min.y();
  double top = boxes[0].max.y();
  heights.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    bottom = std::min(bottom, boxes[i].min.y());
    top = std::max(top, boxes[i].max.y());
    heights[i] = boxes[i].max.y() - boxes[i].min.y();
  }
  const auto middle = heights.begin() + static_cast<std::ptrdiff_t>(heights.size() / 2);
  std::nth_element(heights.begin(), middle, heights.end());
  const double range = top - bottom;
  const double most = static_cast<double>(boxes.size());
  double height = 2.0 * *middle;
  if (!(height > 0.0) || range / height > most) height = range / most;
  if (!(height > 0.0) || !std::isfinite(height) || !std::isfinite(bottom)) return bands;
  bands.bottom = bottom;
  bands.height = height;
  bands.count = static_cast<int>(std::min(range / height, most)) + 1;
  return bands;
}

// The pairs of band `band`'s boxes [first, last) (in x order) that overlap and whose overlap's
// bottom lies in this band, appended to `found`.
void sweep_band(const SweepMemory& memory, const Bands& bands, int band,
                std::vector<BodyPair>& found) {
  const std::vector<Aabb>& banded = memory.banded;
  const auto first = static_cast<std::size_t>(memory.band_start[band]);
  const auto last = static_cast<std::size_t>(memory.band_start[band + 1]);
  for (std::size_t k = first; k < last; ++k) {
    const Aabb& box = banded[k];
    // only the boxes starting left of this box's right edge can overlap it in x
    for (std::size_t l = k + 1; l < last && banded[l].min.x() <= box.max.x(); ++l) {
      // and they must overlap in y too, found in the band of the overlap's bottom only
      if (!box.overlaps(banded[l])) continue;
      if (bands.of(std::max(box.min.y(), banded[l].min.y())) != band) continue;
      const int a = memory.banded_body[k];
      const int b = memory.banded_body[l];
      found.push_back({std::min(a, b), std::max(a, b)});
    }
  }
}

}  // namespace

void sort_and_sweep(const std::vector<Aabb>& boxes, SweepMemory& memory,
                    std::vector<BodyPair>& pairs, Workers* workers) {
  std::vector<int>& order = memory.order;
  // 1. sort by min.x, equal edges in index order
  const auto before = [&](int a, int b) {
    return boxes[a].min.x() < boxes[b].min.x() || (boxes[a].min.x() == boxes[b].min.x() && a < b);
  };
  const auto sort = [&] {
    if (order.size() != boxes.size()) {
      order.resize(boxes.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), before);
    } else {
      insertion_sort(order, before);
    }
  };
  // 2. the boxes band by band, each band's in x order, side by side for the sweep. Each run
  // takes a run of the x order: it counts its boxes in each band, then lists them there after
  // the runs before it, so that each band's boxes stay in x order. The bands are chosen while
  // the boxes are sorted (neither splits into runs; the bands read only the boxes).
  Bands bands;
  run_side_by_side(workers, sort, [&] { bands = choose_bands(boxes, memory.heights); });
  const int runs = runs_on(workers);
  memory.band_fill_of_run.resize(runs);
  memory.reach.resize(order.size());
  run_on(workers, [&](int t) {
    std::vector<int>& count = memory.band_fill_of_run[t];
    count.assign(static_cast<std::size_t>(bands.count), 0);
    const auto [first, last] = share_of(order.size(), t, runs);
    for (std::size_t k = first; k < last; ++k) {
      const Aabb& box = boxes[order[k]];
      const std::array<int, 2> reach{bands.of(box.min.y()), bands.of(box.max.y())};
      memory.reach[k] = reach;
      for (int b = reach[0]; b <= reach[1]; ++b) ++count[b];
    }
  });
  // where each band begins, and where in it each run's boxes begin (its fill)
  std::vector<int>& start = memory.band_start;
  places_by_item(memory.band_fill_of_run, runs, static_cast<std::size_t>(bands.count), start);
  memory.banded.resize(static_cast<std::size_t>(start.back()));
  memory.banded_body.resize(memory.banded.size());
  run_on(workers, [&](int t) {
    std::vector<int>& fill = memory.band_fill_of_run[t];
    const auto [first, last] = share_of(order.size(), t, runs);
    for (std::size_t k = first; k < last; ++k) {
      const int body = order[k];
      for (int b = memory.reach[k][0]; b <= memory.reach[k][1]; ++b) {
        const int at = fill[b]++;
        memory.banded[at] = boxes[body];
        memory.banded_body[at] = body;
      }
    }
  });
  // 3. sweep: each run takes the bands that start in its share of the listed boxes
  memory.found_of_run.resize(runs);
  const auto band_at = [&](std::size_t listed) {
    return static_cast<int>(std::lower_bound(start.begin(), start.end() - 1, listed) -
                            start.begin());
  };
  run_on(workers, [&](int t) {
    const auto [first, last] = share_of(memory.banded.size(), t, runs);
    std::vector<BodyPair>& found = memory.found_of_run[t];
    found.clear();
    const int end = t + 1 == runs ? bands.count : band_at(last);
    for (int band = band_at(first); band < end; ++band) sweep_band(memory, bands, band, found);
  });
  // 4. sorted by (first, second): each run counts its pairs by first body; the bodies' places
  // follow one another, and within a body's the runs' in order; each run puts its pairs in
  // place, then each body's few pairs of its share of the bodies in order by second
  memory.first_next_of_run.resize(runs);
  run_on(workers, [&](int t) {
    std::vector<int>& count = memory.first_next_of_run[t];
    count.assign(boxes.size(), 0);
    for (const BodyPair& pair : memory.found_of_run[t]) ++count[pair.first];
  });
  std::vector<int>& first_start = memory.first_start;
  places_by_item(memory.first_next_of_run, runs, boxes.size(), first_start);
  pairs.resize(static_cast<std::size_t>(first_start.back()));
  run_on(workers, [&](int t) {
    std::vector<int>& next = memory.first_next_of_run[t];
    for (const BodyPair& pair : memory.found_of_run[t]) pairs[next[pair.first]++] = pair;
  });
  run_on(workers, [&](int t) {
    const auto [first_body, last_body] = share_of(boxes.size(), t, runs);
    for (std::size_t b = first_body; b < last_body; ++b) {
      for (int k = first_start[b] + 1; k < first_start[b + 1]; ++k) {
        const BodyPair pair = pairs[k];
        int l = k;
        for (; l > first_start[b] && pair.second < pairs[l - 1].second; --l) {
          pairs[l] = pairs[l - 1];
        }
        pairs[l] = pair;
      }
    }
  });
}

}  // namespace lamina
