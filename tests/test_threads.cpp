// Threads (issue 19): the worker team and its shares, and a step taken on 2 and 3 threads giving
// the one-thread numbers bit for bit: every body's state (PGS's λ alone: test_pgs_threads.cpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "contact/contact_cache.h"
#include "parallel/workers.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"
#include "support/world_state.h"

using namespace lamina;

namespace {

// Five boxes falling apart in the air, those named in `thrown` thrown sideways at 1e308 m/s, the
// first to the right and the others to the left (two thrown the same way would be at the same
// x, rounded, after one step, and collide): a thrown box's x overflows to ±inf in step k = 107
// (1e308 m/s × 108/60 s > 1.8e308 m).
Scene boxes_thrown(const std::vector<std::size_t>& thrown) {
  Scene scene;
  scene.name = "thrown";
  for (std::size_t i = 0; i < 5; ++i) {
    BodyDescription box;
    box.name = "box" + std::to_string(i);
    box.position = {3.0 * static_cast<double>(i), 100.0};
    scene.bodies.push_back(box);
  }
  for (const std::size_t i : thrown) {
    scene.bodies[i].velocity = {i == thrown[0] ? 1e308 : -1e308, 0.0};
  }
  return scene;
}

}  // namespace

TEST_SUITE("Threads") {
  TEST_CASE("shares are consecutive, cover every item once and differ by at most one") {
    for (std::size_t count : {0u, 1u, 2u, 7u, 64u, 1001u}) {
      for (int parts = 1; parts <= 9; ++parts) {
        CAPTURE(count);
        CAPTURE(parts);
        std::size_t next = 0, smallest = count, largest = 0;
        for (int part = 0; part < parts; ++part) {
          const auto [first, last] = share_of(count, part, parts);
          CHECK(first == next);  // consecutive, in order
          CHECK(last >= first);
          smallest = std::min(smallest, last - first);
          largest = std::max(largest, last - first);
          next = last;
        }
        CHECK(next == count);  // every item, once
        CHECK(largest - smallest <= 1);
      }
    }
  }

  TEST_CASE("a team runs each share once, share 0 on the calling thread, all at once") {
    Workers workers(3);
    REQUIRE(workers.count() == 3);
    for (int round = 0; round < 50; ++round) {  // the team is reused, as a World's steps reuse it
      std::vector<std::thread::id> ran_on(3);
      std::atomic<int> calls{0};
      std::atomic<int> arrived{0};
      workers.run([&](int t) {
        ran_on[static_cast<std::size_t>(t)] = std::this_thread::get_id();
        ++calls;
        // every share waits for all three to have started: only shares run at once get past
        ++arrived;
        while (arrived.load() < 3) std::this_thread::yield();
      });
      CHECK(calls.load() == 3);
      CHECK(ran_on[0] == std::this_thread::get_id());
      CHECK(ran_on[1] != ran_on[0]);
      CHECK(ran_on[2] != ran_on[0]);
      CHECK(ran_on[2] != ran_on[1]);
    }
  }

  TEST_CASE("a team spins only when each of its threads can have a core of its own") {
    // A larger team waits sleeping: spinning, a thread without a core holds up the one it waits
    // for by a time slice (golden scenes on 3 threads of 2 cores: 100 times slower).
    const int cores = machine_cores();
    REQUIRE(cores >= 1);  // Linux gives the process's CPU affinity
    CHECK(cores <= static_cast<int>(std::thread::hardware_concurrency()));
    CHECK(Workers(1).spins());
    CHECK(Workers(std::min(cores, 64)).spins());
    if (cores < 64) {
      Workers larger(cores + 1);
      CHECK_FALSE(larger.spins());
      // and it works all the same: each share once, sleeping between the runs
      std::vector<int> ran(static_cast<std::size_t>(cores + 1), 0);
      for (int round = 0; round < 20; ++round) {
        larger.run([&](int t) { ++ran[static_cast<std::size_t>(t)]; });
      }
      CHECK(std::count(ran.begin(), ran.end(), 20) == cores + 1);
    }
  }

  TEST_CASE("an exception in a worker's share reaches the caller, and the team goes on") {
    Workers workers(2);
    CHECK_THROWS_AS(workers.run([](int t) {
                      if (t == 1) throw std::runtime_error("share 1 failed");
                    }),
                    std::runtime_error);
    int ran = 0;
    workers.run([&](int t) {
      if (t == 0) ++ran;
    });
    CHECK(ran == 1);
    CHECK_THROWS_AS(Workers(0), std::invalid_argument);
    CHECK_THROWS_AS(Workers(65), std::invalid_argument);
  }

  TEST_CASE("a waiting thread sees everything written before the count it waited for") {
    // Progress publishes with release and waits with acquire: the reader must see each value
    // the writer stored before publishing its count, never an older one.
    Workers workers(2);
    Progress progress;
    std::vector<long> data(100000, -1);
    long mismatches = 0;
    workers.run([&](int t) {
      if (t == 0) {
        for (long i = 0; i < static_cast<long>(data.size()); ++i) {
          data[static_cast<std::size_t>(i)] = i;
          progress.publish(i + 1);
        }
      } else {
        for (long i = 0; i < static_cast<long>(data.size()); ++i) {
          for (int turns = 0; progress.value() < i + 1;) workers.wait_a_turn(turns);
          if (data[static_cast<std::size_t>(i)] != i) ++mismatches;
        }
      }
    });
    CHECK(mismatches == 0);
  }

  TEST_CASE("a team's thread t takes runs t and 2T − 1 − t of the 2T runs, each once") {
    // 3 threads: 6 runs, thread 0 runs 0 and 5 (on the calling thread), 1 runs 1 and 4, 2 runs 2
    // and 3 — the parts PGS's threads take (test_pgs_threads), so each thread reads again what it
    // wrote in the pieces before
    Workers workers(3);
    REQUIRE(runs_on(&workers) == 6);
    CHECK(runs_on(nullptr) == 1);
    std::array<std::thread::id, 6> ran_on{};
    std::array<std::atomic<int>, 6> calls{};
    run_on(&workers, [&](int run) {
      ran_on[static_cast<std::size_t>(run)] = std::this_thread::get_id();
      ++calls[static_cast<std::size_t>(run)];
    });
    for (const std::atomic<int>& c : calls) CHECK(c.load() == 1);
    CHECK(ran_on[0] == std::this_thread::get_id());
    CHECK(ran_on[5] == ran_on[0]);
    CHECK(ran_on[4] == ran_on[1]);
    CHECK(ran_on[3] == ran_on[2]);
    CHECK(ran_on[1] != ran_on[0]);
    CHECK(ran_on[2] != ran_on[0]);
    CHECK(ran_on[2] != ran_on[1]);
    int alone = -1;
    run_on(nullptr, [&](int run) { alone = run; });
    CHECK(alone == 0);  // no team: one run, on the calling thread
  }

  TEST_CASE("each run's items go after the runs before it: run_starts") {
    // 6 runs of 3 threads counting 3, 0, 5, 1, 0 and 4 (each on its own thread): starts 0, 3, 3,
    // 8, 9, 9 and the total 13
    Workers workers(3);
    const std::array<std::size_t, 6> counts{3, 0, 5, 1, 0, 4};
    const RunStarts starts =
        run_starts(&workers, [&](int run) { return counts[static_cast<std::size_t>(run)]; });
    const std::array<std::size_t, 7> expected{0, 3, 3, 8, 9, 9, 13};
    for (std::size_t r = 0; r < expected.size(); ++r) CHECK(starts[r] == expected[r]);
    CHECK(run_starts(nullptr, [](int) { return std::size_t{7}; })[1] == 7);  // one run, no team
  }

  TEST_CASE("the first non-finite body the threads find is the first in the order added") {
    // Shares of the five bodies: [0, 3) and [3, 5) on 2 threads, [0, 2), [2, 4), [4, 5) on 3.
    // One thrown box in the last share, then one in the first share and one in the last: the
    // step's answer is the first such box, found by a scan of every body here, in step 107
    // (exact: the overflow above) and not before.
    const std::vector<std::vector<std::size_t>> cases{{4}, {1, 4}};
    for (const std::vector<std::size_t>& thrown : cases) {
      for (const int threads : {1, 2, 3}) {
        CAPTURE(thrown.size());
        CAPTURE(threads);
        const Scene scene = boxes_thrown(thrown);
        WorldSettings settings = world_settings(scene);
        settings.threads = threads;
        settings.threads_min_bodies = 0;  // five bodies, stepped on the threads under test
        World world = build_world(scene, settings);
        CHECK_FALSE(world.first_non_finite_body());  // no step yet
        for (int k = 0; k < 108; ++k) {
          world.step();
          std::optional<std::size_t> scanned;
          for (std::size_t i = 0; i < world.bodies().size() && !scanned; ++i) {
            const RigidBody& b = world.bodies()[i];
            const bool finite = b.x.allFinite() && b.q.coeffs().allFinite() && b.v.allFinite() &&
                                b.angular_velocity.allFinite();
            if (!finite) scanned = i;
          }
          CHECK(world.first_non_finite_body() == scanned);
          if (k < 107) CHECK_FALSE(scanned);
        }
        CHECK(world.first_non_finite_body() == std::optional<std::size_t>(thrown[0]));
      }
    }
  }


  TEST_CASE("the largest team, 64 threads in 128 runs, steps a pile as one thread does") {
    // Every piece of the step cut into 128 runs (most of them empty for a pyramid of 10 boxes):
    // the runs' tables hold them all (with the sanitizers on, UBSan stops at a table of 64 runs
    // indexed past its end), and the state is the one-thread state bit for bit.
    World one = world_of("pyramid:4", "pgs", 1);
    World team = world_of("pyramid:4", "pgs", max_threads);
    for (int k = 0; k < 5; ++k) {
      one.step();
      team.step();
    }
    CHECK(state_bytes(team) == state_bytes(one));
  }

  TEST_CASE("the two solves side by side keep the state of a reported step, which takes turns") {
    // Without a report a World sweeps split impulse's position MLCP beside the velocity MLCP
    // (PgsSolver::solve_both); a reported step solves the two one after the other, recording
    // each. 60 steps of pyramid:40, whose bottom contacts sink past the slop (a push-out on most
    // steps: docs/performance.md), must give the same state bit for bit, on one thread and on
    // two, by `pgs` and by `islands` (one island, swept by PGS).
    for (const std::string solver : {"pgs", "islands"}) {
      for (const int threads : {1, 2}) {
        CAPTURE(solver);
        CAPTURE(threads);
        World plain = world_of("pyramid:40", solver, threads);
        World reported = world_of("pyramid:40", solver, 1);
        int pushed = 0;  // steps whose position MLCP was large enough to sweep in parts, and moved
        for (int k = 0; k < 60; ++k) {
          plain.step();
          WorldReport report;
          reported.step(report);
          const StepReport& position = report.position;
          if (position.mlcp.row_count() >= 512 && !position.solution.lambda.isZero(0.0)) ++pushed;
        }
        CHECK(state_bytes(plain) == state_bytes(reported));
        CHECK(pushed >= 30);  // the position MLCP was solved on most steps: the check can fail
        MESSAGE(solver << " on " << threads << ": " << pushed << " of 60 steps pushed out");
      }
    }
  }

  TEST_CASE("chapter 6's block and exact methods step on two threads as on one, bit for bit") {
    // Their solves run on one thread; F_c = Jᵀ λ and the integration (finish_step) on the
    // team, each thread its own runs of the bodies, every body's sum in row order. pyramid:6
    // is one island small enough for `exact`'s pivoting.
    for (const std::string solver : {"block", "exact"}) {
      CAPTURE(solver);
      World one = world_of("pyramid:6", solver, 1);
      World two = world_of("pyramid:6", solver, 2);
      for (int k = 0; k < 60; ++k) {
        one.step();
        two.step();
      }
      CHECK(state_bytes(two) == state_bytes(one));
    }
  }

  TEST_CASE("a pyramid stepped with the contact cache off keeps the one-thread state bit for bit") {
    // With the cache off every pair is new on every step, so the cache's merge cuts its runs by
    // the fresh collisions (the longer list; with the cache on the first step is cut so too and
    // the later ones by the cached pairs: "a pyramid stepped on 2 and 3 threads" below). Each
    // pair is merged once, in its run, and the state is the one-thread state bit for bit: 60
    // steps of pyramid:20 on 1, 2 and 3 threads.
    std::vector<std::vector<unsigned char>> states;
    for (const int threads : {1, 2, 3}) {
      Scene scene = builtin_scene("pyramid:20");
      scene.solver = "pgs";
      WorldSettings settings = world_settings(scene);
      settings.threads = threads;
      settings.cache.enabled = false;
      World world = build_world(scene, settings);
      for (int k = 0; k < 60; ++k) world.step();
      states.push_back(state_bytes(world));
    }
    CHECK(states[1] == states[0]);
    CHECK(states[2] == states[0]);
  }

  TEST_CASE("the cache's merge on threads: new pairs among kept ones, the runs cut at kept ones") {
    // 24 boxes on a ground box, every third pair kept from a first update ((0, 1), (0, 4), …),
    // then all 24 found again: the fresh collisions outnumber the kept pairs, so the runs cut
    // the fresh list into equal shares (of 24 in 4 runs on 2 threads: at (0, 7), (0, 13),
    // (0, 19), each a kept pair) and the kept pairs at the same pairs. Each kept pair must be
    // merged with its own fresh collision, in one run: the same pairs, in the same order, with
    // the same contacts as one thread's merge (a kept pair cut from its collision would be kept
    // twice, once with its old point and once as a new pair).
    constexpr int boxes = 24;
    std::vector<Shape> shapes{Shape::box(50.0, 0.5)};
    std::vector<Pose2> poses{Pose2{Vec2(0.0, -0.5)}};
    std::vector<FreshCollision> all;
    std::vector<FreshCollision> every_third;
    for (int i = 1; i <= boxes; ++i) {
      shapes.push_back(Shape::box(0.5, 0.5));
      poses.push_back(Pose2{Vec2(1.5 * i, 0.5)});
      Collision touch;
      touch.point = Vec2(1.5 * i - 0.5, 0.0);
      all.push_back({BodyPair{0, i}, touch});
      if (i % 3 == 1) every_third.push_back(all.back());
    }
    const std::vector<Material> materials(shapes.size());
    ContactCache kept;
    kept.update(every_third, {}, poses, shapes, materials, CacheSettings{});
    REQUIRE(kept.pairs().size() == every_third.size());
    // the boxes moved a little to the right: a kept point and a new one are told apart
    for (std::size_t b = 1; b < poses.size(); ++b) poses[b].x.x() += 0.01;
    for (FreshCollision& f : all) f.collision.point.x() += 0.01;
    ContactCache one = kept;
    one.update(all, {}, poses, shapes, materials, CacheSettings{});
    REQUIRE(one.pairs().size() == all.size());
    for (const int threads : {2, 3}) {
      CAPTURE(threads);
      Workers workers(threads);
      ContactCache team = kept;
      team.update(all, {}, poses, shapes, materials, CacheSettings{}, &workers);
      REQUIRE(team.pairs().size() == one.pairs().size());
      for (std::size_t k = 0; k < one.pairs().size(); ++k) {
        const ContactPair& a = one.pairs()[k];
        const ContactPair& b = team.pairs()[k];
        CHECK(b.bodies == a.bodies);
        REQUIRE(b.count == a.count);
        for (int c = 0; c < a.count; ++c) {
          CHECK(b.contacts[c].point == a.contacts[c].point);
          CHECK(b.contacts[c].origin == a.contacts[c].origin);
        }
      }
    }
  }

  TEST_CASE("a pyramid stepped on 2 and 3 threads keeps the one-thread state bit for bit") {
    // 120 steps of pyramid:20 (landing, then resting under the cache's warm start): the narrow
    // phase split between the threads, the MLCPs packed and the velocity and position sweeps
    // run on them, the bodies integrated on them; by `pgs` and by `islands` (one island of
    // 1700-odd rows, swept by PGS).
    for (const std::string solver : {"pgs", "islands"}) {
      CAPTURE(solver);
      World one = world_of("pyramid:20", solver, 1);
      World two = world_of("pyramid:20", solver, 2);
      World three = world_of("pyramid:20", solver, 3);
      for (int k = 0; k < 120; ++k) {
        one.step();
        two.step();
        three.step();
      }
      const std::vector<unsigned char> expected = state_bytes(one);
      CHECK(state_bytes(two) == expected);
      CHECK(state_bytes(three) == expected);
    }
  }
}
