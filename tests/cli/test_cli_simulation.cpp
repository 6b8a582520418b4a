// `lamina run` on a run that diverges: the scene reader refuses every value that could make a
// run diverge (engine/scene/scene_limits.h), so these scenes are made in code and run
// in-process, through the same run_scene() the command calls. A step that leaves a body
// non-finite stops the run with one line naming the body and the step, exit code 3, and the
// trace and frames of every step before it complete.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../render_test_frame.h"
#include "app/cli/exit_codes.h"
#include "app/cli/run_command.h"
#include "app/cli/simulation.h"
#include "scene/scene_world.h"
#include "trace/trace_json.h"

using namespace lamina;
using namespace lamina::cli;
namespace fs = std::filesystem;
using render::testing::ScratchFolder;

namespace {

// A 1 m box thrown along the ground at 1e308 m/s, not far below the largest double (1.8e308):
// x grows by 1.7e306 m a step and overflows to inf at step 108. The scene reader refuses any
// speed above 1e4 m/s (scene_limits.h), so no scene file can hold it.
Scene thrown_box() {
  Scene scene;
  scene.name = "thrown";
  BodyDescription ground;
  ground.name = "ground";
  ground.shape.half_extents = {5.0, 0.5};
  ground.position = {0.0, -0.5};
  ground.is_static = true;
  BodyDescription box;
  box.name = "box3";
  box.position = {0.0, 0.5};
  box.velocity = {1e308, 0.0};
  scene.bodies = {ground, box};
  return scene;
}

// A 1 m box of density 1e300 resting on the ground: its inertia overflows in the first step,
// which leaves θ and ω NaN (scene_limits.h measured this end of the density range).
Scene heavy_box() {
  Scene scene = thrown_box();
  scene.name = "heavy";
  scene.bodies[1].velocity = {0.0, 0.0};
  scene.bodies[1].density = 1e300;
  return scene;
}

// How a run stopped: the steps it took, its RunStopped's message and exit code ("", 0: it ran on).
struct Stop {
  long steps_taken = 0;
  std::string message;
  int exit_code = 0;
};

Stop step_until_stopped(Simulation& simulation, long most_steps) {
  try {
    while (simulation.steps_taken() < most_steps) simulation.step();
  } catch (const RunStopped& e) {
    return {simulation.steps_taken(), e.what(), e.exit_code()};
  }
  return {simulation.steps_taken(), "", 0};
}

std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// A PNG ends with its IEND chunk: length 0, "IEND", CRC ae 42 60 82.
bool ends_with_iend(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return ends_with(bytes, iend);
}

// The files below `folder`, sorted.
std::vector<fs::path> files_in(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(folder)) {
    if (e.is_regular_file()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The step k (counted from 0) at which a run diverges, found by stepping its world alone; −1
// when none of the first 1000 does.
long diverging_step(const Scene& scene) {
  World world = build_world(scene, world_settings(scene));
  for (long step = 0; step < 1000; ++step) {
    world.step();
    if (world.first_non_finite_body()) return step;
  }
  return -1;
}

}  // namespace

TEST_SUITE("LaminaRun") {
  TEST_CASE("a step that leaves a body non-finite stops the run, naming the body and the step") {
    const Scene scene = thrown_box();
    const long diverges = diverging_step(scene);
    REQUIRE(diverges == 107);  // 1e308 m/s × 108/60 s > 1.8e308 m: the 108th step, k = 107
    Simulation simulation(scene, world_settings(scene), "thrown.json");
    const Stop stop = step_until_stopped(simulation, 1000);
    CHECK(stop.exit_code == exit_diverged);
    CHECK(stop.steps_taken == diverges);  // steps 0 .. k − 1: the step that diverged is not taken
    const std::string expected = "thrown.json: step " + std::to_string(diverges) +
                                 ": body \"box3\" is no longer finite (x = (inf, ";
    CHECK_MESSAGE(stop.message.rfind(expected, 0) == 0, stop.message);
    CHECK(stop.message.find('\n') == std::string::npos);
  }

  TEST_CASE("a run that diverges keeps the trace and frames of every step before, complete") {
    const ScratchFolder scratch("cli-diverge");
    const Scene scene = thrown_box();
    const long diverges = diverging_step(scene);
    RunOptions options;
    options.scene = "thrown.json";
    options.steps = 1000;
    options.trace = scratch.path() / "trace.jsonl";
    options.frames = scratch.path() / "frames";
    options.every = 4;
    options.render.size = {64, 36};
    Stop stop;
    try {
      run_scene(scene, options);
    } catch (const RunStopped& e) {
      stop = {0, e.what(), e.exit_code()};
    }
    CHECK(stop.exit_code == exit_diverged);
    const long kept = diverges;                    // steps 0 .. kept − 1
    const long frames = (kept - 1) / options.every + 1;  // steps 0, 4, 8, ... up to the last kept
    const std::string tail = "; trace -> " + options.trace->string() + " holds steps 0.." +
                             std::to_string(kept - 1) + ", " + std::to_string(frames) +
                             " frames -> " + options.frames->string();
    CHECK_MESSAGE(ends_with(stop.message, tail), stop.message);

    const std::vector<std::string> lines = lines_of(*options.trace);
    REQUIRE(static_cast<long>(lines.size()) == kept);
    for (long i = 0; i < kept; ++i) {
      const TraceStep step = parse_trace_line(lines[static_cast<std::size_t>(i)]);
      CHECK(step.step == i);
      CHECK(std::isfinite(step.bodies.at(0).position[1]));
    }
    std::vector<fs::path> pngs;
    for (const fs::path& file : files_in(scratch.path())) {
      CHECK_MESSAGE(file.extension() != ".tmp", file.string());
      if (file.extension() == ".png") pngs.push_back(file);
    }
    CHECK(static_cast<long>(pngs.size()) == frames);
    for (const fs::path& png : pngs) CHECK_MESSAGE(ends_with_iend(png), png.string());
  }

  TEST_CASE("a CSV trace of a run that diverges keeps both its files") {
    const ScratchFolder scratch("cli-diverge-csv");
    RunOptions options;
    options.scene = "thrown.json";
    options.trace = scratch.path() / "trace.csv";
    CHECK_THROWS_AS(run_scene(thrown_box(), options), RunStopped);
    CHECK(fs::exists(scratch.path() / "trace.csv"));
    CHECK(fs::exists(scratch.path() / "trace.contacts.csv"));
    CHECK(files_in(scratch.path()).size() == 2);
  }

  TEST_CASE("a run that diverges in its first step keeps an empty trace and no frame") {
    const ScratchFolder scratch("cli-diverge-first");
    RunOptions options;
    options.scene = "heavy.json";
    options.steps = 10000000;  // the most: the run stops at the step that diverges
    options.allow_large = true;  // 10⁷ frames asked for, none drawn
    options.trace = scratch.path() / "trace.jsonl";
    options.frames = scratch.path() / "frames";
    options.render.size = {64, 36};
    std::string message;
    try {
      run_scene(heavy_box(), options);
    } catch (const RunStopped& e) {
      message = e.what();
      CHECK(e.exit_code() == exit_diverged);
    }
    const std::string start = "heavy.json: step 0: body \"box3\" is no longer finite (x = (";
    // frame 0 would show what step 0 solved, and step 0 diverged
    const std::string end = "); trace -> " + options.trace->string() +
                            " holds no steps, 0 frames -> " + options.frames->string();
    CHECK_MESSAGE(message.rfind(start, 0) == 0, message);
    CHECK_MESSAGE(ends_with(message, end), message);
    CHECK_MESSAGE(message.find("nan") != std::string::npos, message);
    CHECK(fs::file_size(*options.trace) == 0);
    CHECK(files_in(scratch.path()) == std::vector<fs::path>{*options.trace});
  }

  TEST_CASE("lamina run --frames simulates its run once: one World step per step of the run") {
    // The frames' view is fitted to everything the run sweeps, so it is known only at the end:
    // the run is recorded as it is simulated, then drawn (frame_recording.h), not simulated
    // twice. Counted over every World of the process, so a second simulation would show.
    const ScratchFolder scratch("cli-once");
    RunOptions options;
    options.scene = "box-on-ground-tilted";
    options.steps = 50;
    options.every = 5;
    options.frames = scratch.path() / "frames";
    options.trace = scratch.path() / "trace.jsonl";
    options.render.size = {64, 36};
    const long before = World::steps_in_process();
    run_scene(options);
    CHECK(World::steps_in_process() - before == 50);
    CHECK(files_in(*options.frames).size() == 10);  // steps 0, 5, ..., 45
    CHECK(lines_of(*options.trace).size() == 50);
  }
}
