// A World's times of its phases (contact/step_times.h): every phase of a pyramid's step is
// timed, the phases add up to the steps' wall-clock time, a chapter-6 method's steps 5–7 count as
// one phase, and `since` and `step_times_after_first` leave the steps before out. Times are the
// machine's, so the checks are of what must hold on any machine: a phase that does work takes
// time, the phases lie inside the steps, and the sums of some steps are those of all less those
// of the steps before, exactly.
#include <doctest/doctest.h>

#include <chrono>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

using namespace lamina;

namespace {

World pyramid_world(const std::string& solver) {
  Scene scene = builtin_scene("pyramid:10");
  scene.solver = solver;
  return build_world(scene, world_settings(scene));
}

constexpr StepPhase every_phase[] = {StepPhase::forces, StepPhase::collision, StepPhase::cache,
                                     StepPhase::rows,   StepPhase::solve,     StepPhase::integrate,
                                     StepPhase::checks};

}  // namespace

TEST_CASE("a World's phases are timed, and add up to its steps' time") {
  World world = pyramid_world("pgs");
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < 30; ++k) world.step();
  const std::chrono::duration<double> wall_time = std::chrono::steady_clock::now() - start;
  const double wall = wall_time.count();
  const StepTimes& times = world.step_times();
  CHECK(times.steps == 30);
  // each phase works on the 55 boxes or their contacts every step: never no time at all (the
  // steady clock counts nanoseconds; the shortest phase, F_ext = m g on 55 bodies, takes about
  // a hundred)
  for (const StepPhase phase : every_phase) {
    INFO(phase_name(phase));
    CHECK(times.of(phase) > 0.0);
  }
  // the phases follow each other inside the steps: their sum is at most the loop's time, and
  // all of it but the few clock readings and calls between the steps (at least half even if the
  // machine took the thread away between two steps for as long as all the steps took)
  CHECK(times.total() <= wall);
  CHECK(times.total() >= 0.5 * wall);
}

TEST_CASE("a chapter-6 method's steps 5 to 7 are one phase, and since() leaves earlier steps out") {
  World world = pyramid_world("islands");
  for (int k = 0; k < 10; ++k) world.step();
  const StepTimes first = world.step_times();
  for (int k = 0; k < 20; ++k) world.step();
  const StepTimes later = world.step_times().since(first);
  CHECK(later.steps == 20);
  CHECK(later.of(StepPhase::solve) > 0.0);
  CHECK(later.of(StepPhase::integrate) == 0.0);  // the method integrates inside its own step
  for (const StepPhase phase : every_phase) {
    INFO(phase_name(phase));
    CHECK(later.of(phase) >= 0.0);
    CHECK(later.of(phase) <= world.step_times().of(phase));
  }
  CHECK(later.total() < world.step_times().total());  // the first 10 steps' time is left out
}

TEST_CASE("step_times_after_first leaves the first step out, and is the first alone") {
  World world = pyramid_world("pgs");
  world.step();
  const StepTimes first = world.step_times();
  // one step: nothing after it to show, so the first step itself (exactly its sums)
  CHECK(world.step_times_after_first().steps == 1);
  CHECK(world.step_times_after_first().total() == first.total());
  for (int k = 0; k < 9; ++k) world.step();
  const StepTimes after = world.step_times_after_first();
  CHECK(after.steps == 9);
  // the sums of steps 1..9 are the sums of steps 0..9 less step 0's, phase by phase, exactly as
  // since() subtracts them
  for (const StepPhase phase : every_phase) {
    INFO(phase_name(phase));
    CHECK(after.of(phase) == world.step_times().since(first).of(phase));
  }
}
