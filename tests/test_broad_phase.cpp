// Chapter 4's broad phase (beyond the text, which omits it): sort and sweep within bands of y,
// on one thread and on teams of threads, against every pair's own overlap test.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "contact/broad_phase.h"
#include "parallel/workers.h"

using namespace lamina;

TEST_SUITE("BroadPhase") {
  std::vector<BodyPair> brute_force(const std::vector<Aabb>& boxes) {
    std::vector<BodyPair> pairs;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
      for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j) {
        if (boxes[i].overlaps(boxes[j])) pairs.push_back({i, j});
      }
    }
    return pairs;  // already sorted by (first, second)
  }

  // The broad phase on one thread (nullptr) and on teams of 2 and 3: the same pairs.
  std::vector<BodyPair> sweep_on(int threads, const std::vector<Aabb>& boxes, SweepMemory& memory) {
    std::vector<BodyPair> pairs;
    if (threads == 1) {
      sort_and_sweep(boxes, memory, pairs);
    } else {
      Workers workers(threads);
      sort_and_sweep(boxes, memory, pairs, &workers);
    }
    return pairs;
  }

  TEST_CASE("sort and sweep finds exactly the overlapping pairs of random scenes, sorted") {
    // Exact: the pairs are a set of integers, checked against every pair's overlap test.
    for (const int threads : {1, 2, 3}) {
      CAPTURE(threads);
      std::mt19937 rng(20240501);
      std::uniform_real_distribution<double> where(0.0, 20.0);
      std::uniform_real_distribution<double> size(0.05, 1.5);
      // one memory for all the scenes: the first is sorted from scratch, the others from the
      // order of the scene before (the insertion sort of a step)
      SweepMemory memory;
      for (int scene = 0; scene < 50; ++scene) {
        std::vector<Aabb> boxes(200);
        for (Aabb& box : boxes) {
          box.min = Vec2(where(rng), where(rng));
          box.max = box.min + Vec2(size(rng), size(rng));
        }
        // A few exactly touching and exactly equal boxes: touching counts as overlapping.
        boxes[1].min = Vec2(boxes[0].max.x(), boxes[0].min.y());
        boxes[1].max = boxes[1].min + Vec2(1.0, 1.0);
        boxes[3] = boxes[2];
        // every fifth scene has a box far above and one far below the rest: the bands then
        // widen (never more bands than boxes) and the far boxes meet nothing
        if (scene % 5 == 4) {
          boxes[4].min = Vec2(5.0, 1e7);
          boxes[4].max = Vec2(6.0, 1e7 + 1.0);
          boxes[5].min = Vec2(5.0, -1e7);
          boxes[5].max = Vec2(6.0, -1e7 + 0.5);
        }
        const std::vector<BodyPair> pairs = sweep_on(threads, boxes, memory);
        const std::vector<BodyPair> expected = brute_force(boxes);
        CHECK(pairs == expected);
        CHECK(std::find(pairs.begin(), pairs.end(), BodyPair{0, 1}) != pairs.end());
      }
    }
  }

  TEST_CASE("sort and sweep on a wall of touching unit boxes: every pair once, band edges too") {
    // 12 columns of 40 unit boxes on a wide floor, every box touching its eight neighbours (the
    // corners too): the median height 1 makes bands 2 high whose edges (y = 2, 4, …) are where
    // boxes touch, so a touching pair's overlap has its bottom exactly on a band's edge. Each
    // pair must be found once, in one band (exact: against the brute force).
    std::vector<Aabb> boxes;
    boxes.push_back({Vec2(-50.0, -1.0), Vec2(50.0, 0.0)});
    for (int column = 0; column < 12; ++column) {
      for (int row = 0; row < 40; ++row) {
        boxes.push_back({Vec2(column, row), Vec2(column + 1.0, row + 1.0)});
      }
    }
    const std::vector<BodyPair> expected = brute_force(boxes);
    // 12 floor pairs; in the wall 12·39 vertical, 11·40 sideways, 2·11·39 corner pairs
    REQUIRE(expected.size() == 12 + 12 * 39 + 11 * 40 + 2 * 11 * 39);
    for (const int threads : {1, 2, 3}) {
      CAPTURE(threads);
      SweepMemory memory;
      CHECK(sweep_on(threads, boxes, memory) == expected);
    }
  }

  TEST_CASE("the pairs come out in body order whatever the boxes' positions") {
    // Bodies listed right to left: the sweep meets 2, 1, 0, but the pairs are (0,1), (1,2).
    const std::vector<Aabb> boxes{{Vec2(2.0, 0.0), Vec2(3.0, 1.0)},
                                  {Vec2(1.0, 0.0), Vec2(2.0, 1.0)},
                                  {Vec2(0.0, 0.0), Vec2(1.0, 1.0)}};
    SweepMemory memory;
    std::vector<BodyPair> pairs;
    sort_and_sweep(boxes, memory, pairs);
    REQUIRE(pairs.size() == 2);
    CHECK(pairs[0] == BodyPair{0, 1});
    CHECK(pairs[1] == BodyPair{1, 2});
  }
}
