// Threads (issue 19): the worker team and its shares, and a step taken on 2 and 3 threads giving
// the one-thread numbers bit for bit — λ of PGS's sweeps, and every body's state.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "constraints/pgs_solver.h"
#include "parallel/workers.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

using namespace lamina;

namespace {

// The bytes of a vector of doubles: equal bytes, equal bits (−0 and +0, and NaNs, told apart).
std::vector<unsigned char> bytes_of(const double* values, std::size_t count) {
  std::vector<unsigned char> bytes(count * sizeof(double));
  if (count > 0) std::memcpy(bytes.data(), values, bytes.size());
  return bytes;
}

std::vector<unsigned char> state_bytes(const World& world) {
  std::vector<double> values;
  for (const RigidBody& b : world.bodies()) {
    values.insert(values.end(), b.x.data(), b.x.data() + 3);
    values.insert(values.end(), b.q.coeffs().data(), b.q.coeffs().data() + 4);
    values.insert(values.end(), b.v.data(), b.v.data() + 3);
    values.insert(values.end(), b.angular_velocity.data(), b.angular_velocity.data() + 3);
  }
  return bytes_of(values.data(), values.size());
}

World world_of(const std::string& scene_name, const std::string& solver, int threads) {
  Scene scene = builtin_scene(scene_name);
  scene.solver = solver;
  WorldSettings settings = world_settings(scene);
  settings.threads = threads;
  return build_world(scene, settings);
}

// The velocity MLCP of pyramid:20 after `steps` steps and its warm start: 1700-odd rows.
StepReport pyramid_mlcp(int steps, Scene scene = builtin_scene("pyramid:20")) {
  scene.solver = "pgs";
  World world = build_world(scene, world_settings(scene));
  for (int k = 0; k < steps; ++k) world.step();
  WorldReport report;
  world.step(report);
  return report.velocity;
}

// λ after `sweeps` sweeps from the report's warm start, by `solver`.
std::vector<unsigned char> solved(PgsSolver& solver, const StepReport& step, int sweeps,
                                  Pitfalls pitfalls = {}) {
  std::vector<double> lambda(step.lambda_exp.data(), step.lambda_exp.data() + step.lambda_exp.size());
  SweepResult result;
  solver.solve(step.mlcp, lambda.data(), {sweeps, 0.0, false}, result, pitfalls);
  return bytes_of(lambda.data(), lambda.size());
}

// λ after `sweeps` sweeps by a solver given a team of `threads`, and whether it swept on them.
struct OnThreads {
  std::vector<unsigned char> lambda;
  bool swept_on_threads = false;
};
OnThreads solved_on_threads(int threads, const StepReport& step, int sweeps,
                            Pitfalls pitfalls = {}) {
  Workers workers(threads);
  PgsSolver solver;
  solver.use_workers(&workers);
  OnThreads out;
  out.lambda = solved(solver, step, sweeps, pitfalls);
  out.swept_on_threads = solver.swept_on_threads();
  return out;
}

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

  TEST_CASE("each run's items go after the runs before it: run_starts") {
    // counts 3, 0 and 5 (each run counting on its own thread): starts 0, 3, 3 and the total 8
    Workers workers(3);
    const std::array<std::size_t, 3> counts{3, 0, 5};
    const RunStarts starts =
        run_starts(&workers, [&](int t) { return counts[static_cast<std::size_t>(t)]; });
    CHECK(starts[0] == 0);
    CHECK(starts[1] == 3);
    CHECK(starts[2] == 3);
    CHECK(starts[3] == 8);
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

  TEST_CASE("PGS swept on 2 and 3 threads gives the one-thread λ bit for bit") {
    // The threads' order keeps every body's sequence of updates (pgs_solver.h): λ must be
    // identical, not close. Two moments of the pyramid: early (landing) and settled.
    for (const int steps : {3, 60}) {
      const StepReport step = pyramid_mlcp(steps);
      REQUIRE(step.mlcp.row_count() >= 1000);
      PgsSolver one;
      const std::vector<unsigned char> expected = solved(one, step, 8);
      CHECK_FALSE(one.swept_on_threads());
      for (const int threads : {2, 3}) {
        CAPTURE(steps);
        CAPTURE(threads);
        const OnThreads plain = solved_on_threads(threads, step, 8);
        CHECK(plain.lambda == expected);
        CHECK(plain.swept_on_threads);  // the threads did sweep: the check can fail
        // the pitfall clamp-increment sweeps on threads too, and keeps its own numbers
        PgsSolver one_clamped;
        Pitfalls clamp;
        clamp.add(Pitfall::clamp_increment);
        const OnThreads clamped = solved_on_threads(threads, step, 8, clamp);
        CHECK(clamped.lambda == solved(one_clamped, step, 8, clamp));
        CHECK(clamped.swept_on_threads);
      }
    }
  }

  TEST_CASE("PGS swept in two lanes on one thread gives the row-by-row sweeps' λ bit for bit") {
    // The lanes keep every body's sequence of updates, as the threads do (pgs_solver.h): λ must
    // be identical to the plain sweep's, row after row. Recording the sweeps forces the plain
    // sweep (it measures the residual after each), and recording never changes λ.
    for (const int steps : {3, 60}) {
      const StepReport step = pyramid_mlcp(steps);
      REQUIRE(step.mlcp.row_count() >= 1000);
      for (const int sweeps : {2, 3, 8}) {
        for (const bool clamped : {false, true}) {
          CAPTURE(steps);
          CAPTURE(sweeps);
          CAPTURE(clamped);
          Pitfalls pitfalls;
          if (clamped) pitfalls.add(Pitfall::clamp_increment);
          PgsSolver row_by_row;
          std::vector<double> expected(step.lambda_exp.data(),
                                       step.lambda_exp.data() + step.lambda_exp.size());
          SweepResult recorded;
          row_by_row.solve(step.mlcp, expected.data(), {sweeps, 0.0, true}, recorded, pitfalls);
          CHECK_FALSE(row_by_row.swept_in_lanes());
          PgsSolver lanes;
          CHECK(solved(lanes, step, sweeps, pitfalls) == bytes_of(expected.data(), expected.size()));
          CHECK(lanes.swept_in_lanes());  // the lanes did sweep: the check can fail
        }
      }
    }
  }

  TEST_CASE("the parts' plan is kept while the rows' groups stay, and made again when they change") {
    // A solver keeps the plans of the last two MLCPs it swept (part_plan.h). In its first step
    // the same pyramid with two boxes swapped in the list has as many groups and rows (the
    // same boxes touch), only other bodies in them: its plan must be made again, and each λ
    // must be a fresh solver's bit for bit.
    const StepReport placed = pyramid_mlcp(0);
    Scene swapped_scene = builtin_scene("pyramid:20");
    std::swap(swapped_scene.bodies[10], swapped_scene.bodies[100]);
    const StepReport swapped = pyramid_mlcp(0, swapped_scene);
    REQUIRE(swapped.mlcp.groups().size() == placed.mlcp.groups().size());
    REQUIRE(swapped.mlcp.row_count() == placed.mlcp.row_count());
    PgsSolver kept;
    const auto solve_kept = [&](const StepReport& step, long plans_made) {
      PgsSolver fresh;
      CHECK(solved(kept, step, 8) == solved(fresh, step, 8));
      CHECK(kept.swept_in_lanes());  // the plan was used: the checks can fail
      CHECK(kept.plans_made() == plans_made);
    };
    solve_kept(placed, 1);
    solve_kept(placed, 1);  // kept
    solve_kept(swapped, 2);  // the same sizes, other groups: made again
    solve_kept(placed, 2);  // the plan before it, kept beside it
    solve_kept(swapped, 2);
    solve_kept(pyramid_mlcp(60), 3);  // settled: other contacts
    solve_kept(placed, 4);  // no longer among the last two
  }

  TEST_CASE("rows in no order of place are swept on one thread, to the same λ") {
    // The pyramid's boxes listed in a shuffled order: a box's rows then share bodies with rows
    // all over the order, the threads would wait at nearly every group, and the solver keeps to
    // one thread.
    Scene shuffled = builtin_scene("pyramid:20");
    std::mt19937 rng(19);
    std::shuffle(shuffled.bodies.begin() + 1, shuffled.bodies.end(), rng);  // the ground stays first
    const StepReport step = pyramid_mlcp(30, shuffled);
    REQUIRE(step.mlcp.row_count() >= 1000);
    const OnThreads on_threads = solved_on_threads(2, step, 8);
    PgsSolver one;
    CHECK(on_threads.lambda == solved(one, step, 8));
    CHECK_FALSE(on_threads.swept_on_threads);
    CHECK_FALSE(one.swept_in_lanes());  // nor in two lanes
  }

  TEST_CASE("rows of a few boxes listed far from their neighbours: the threads' λ is one thread's") {
    // A few of the pyramid's boxes swapped with others far away in the list: their rows then
    // share bodies with runs that are not next to theirs, so the two lanes of a thread can both
    // wait, each on a run of another thread (pgs_solver.h). A thread that then waited on one of
    // them alone could wait forever (that run waiting, in turn, on the thread's other lane); the
    // lanes must keep looking at both. Few enough swaps that the plan still sweeps on threads.
    int on_threads_count = 0;
    for (const unsigned seed : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u}) {
      for (const int swaps : {1, 2, 3}) {
        Scene scene = builtin_scene("pyramid:20");
        std::mt19937 rng(seed);
        std::uniform_int_distribution<std::size_t> box(1, scene.bodies.size() - 1);
        for (int k = 0; k < swaps; ++k) std::swap(scene.bodies[box(rng)], scene.bodies[box(rng)]);
        const StepReport step = pyramid_mlcp(10, scene);
        PgsSolver one;
        const std::vector<unsigned char> expected = solved(one, step, 8);
        for (const int threads : {2, 3}) {
          CAPTURE(seed);
          CAPTURE(swaps);
          CAPTURE(threads);
          const OnThreads on_threads = solved_on_threads(threads, step, 8);
          CHECK(on_threads.lambda == expected);
          if (on_threads.swept_on_threads) ++on_threads_count;
        }
      }
    }
    CHECK(on_threads_count >= 24);  // most of the 48 solves did go on threads: the check can fail
    MESSAGE("solves on threads: " << on_threads_count << " of 48");
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
