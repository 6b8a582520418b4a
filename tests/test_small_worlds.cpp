// Small worlds on one thread (issue 19): a World asked for threads takes its steps on them only
// once it has WorldSettings::threads_min_bodies bodies; below, on the calling thread, where a
// small scene's step is faster (docs/performance.md, "Small worlds on one thread"). Either way
// the state is the one-thread state bit for bit.
#include <doctest/doctest.h>

#include <stdexcept>

#include "support/world_state.h"

using namespace lamina;

namespace {

// A World of a ground and one box, stepped 30 times, on `threads` from `threads_min_bodies`.
World box_on_ground(int threads, int threads_min_bodies) {
  WorldSettings settings;
  settings.threads = threads;
  settings.threads_min_bodies = threads_min_bodies;
  World world(settings);
  world.add_static_box(10.0, 0.5, Vec3(0.0, -0.5, 0.0));
  world.add_box(1.0, 0.5, 0.5, Vec3(0.0, 0.6, 0.0));
  for (int k = 0; k < 30; ++k) world.step();
  return world;
}

}  // namespace

TEST_SUITE("Threads") {
  TEST_CASE("a World of fewer bodies than its minimum steps on one thread, with the same bits") {
    // pyramid:4 has 11 bodies (ten boxes and the ground): on two threads from 11 bodies its
    // steps are on the threads, from 12 on the calling thread; after 60 steps the state is the
    // one-thread state byte for byte either way (an identity: the threads change no bit).
    World one = world_of("pyramid:4", "pgs", 1);
    for (int k = 0; k < 60; ++k) one.step();
    REQUIRE(one.bodies().size() == 11);
    CHECK_FALSE(one.stepped_on_threads());  // one thread: no team at all
    for (const int min_bodies : {11, 12}) {
      CAPTURE(min_bodies);
      World two = world_of("pyramid:4", "pgs", 2, min_bodies);
      for (int k = 0; k < 60; ++k) two.step();
      CHECK(two.stepped_on_threads() == (min_bodies == 11));
      CHECK(state_bytes(two) == state_bytes(one));
    }
  }

  TEST_CASE("a World that grows to its minimum goes on to its threads at the next step") {
    // A box on the ground (2 bodies) on two threads from 3 bodies: 30 steps on the calling
    // thread; a second box dropped on the first makes 3, and the next 60 steps are on the
    // threads (PGS's counters and plan made for the team then). The same bits as one thread's.
    World one = box_on_ground(1, 0);
    World two = box_on_ground(2, 3);
    CHECK_FALSE(two.stepped_on_threads());
    for (World* world : {&one, &two}) world->add_box(1.0, 0.5, 0.5, Vec3(0.1, 2.0, 0.0));
    for (int k = 0; k < 60; ++k) {
      one.step();
      two.step();
      if (k == 0) CHECK(two.stepped_on_threads());
    }
    CHECK(state_bytes(two) == state_bytes(one));
    // the dropped box fell onto the first (its centre comes to rest near y = 1.6, dropped from
    // 2.0): a step on the threads that lost its contacts would leave other states to compare
    CHECK(two.bodies()[2].x.y() < 2.0 - 0.1);
  }

  TEST_CASE("by default a World takes threads from 128 bodies: pyramid:16 does, pyramid:15 not") {
    // The minimum measured in docs/performance.md ("Small worlds on one thread": two threads
    // overtake one between about 100 and 140 bodies, pyramids and hexagon pyramids alike); the
    // benchmarks' two-thread pyramids (bases 20, 40 and 80) are all past it.
    CHECK(WorldSettings().threads_min_bodies == 128);
    World small = world_of("pyramid:15", "pgs", 2, WorldSettings().threads_min_bodies);
    World large = world_of("pyramid:16", "pgs", 2, WorldSettings().threads_min_bodies);
    small.step();
    large.step();
    CHECK(small.bodies().size() == 121);
    CHECK_FALSE(small.stepped_on_threads());
    CHECK(large.bodies().size() == 137);
    CHECK(large.stepped_on_threads());
  }

  TEST_CASE("a negative minimum of bodies is refused") {
    WorldSettings settings;
    settings.threads = 2;
    settings.threads_min_bodies = -1;
    CHECK_THROWS_WITH_AS(World{settings}, "world: threads_min_bodies must be ≥ 0, got -1",
                         std::invalid_argument);
  }
}
