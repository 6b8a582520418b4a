#include "lamina/run_command.h"

#include <iostream>

#include "harness/runs.h"
#include "lamina/scene_source.h"
#include "lamina/view_region.h"
#include "lamina/world_scene.h"
#include "scene/scene_world.h"

namespace lamina::cli {
namespace {

const tutorial::TutorialInfo lamina_info{"lamina", "", "", {}, true};

WorldSettings run_settings(const RunOptions& o, Scene& scene) {
  if (o.dt) scene.dt = *o.dt;
  if (o.iterations) scene.iterations = *o.iterations;
  if (o.beta) scene.beta = *o.beta;
  WorldSettings settings = world_settings(scene);
  settings.cache.enabled = !o.no_cache;
  return settings;
}

// A factory for the harness that hands it the one scene, already made.
tutorial::SceneFactory hand_over(Simulation& simulation, const render::Rect& view) {
  return [&simulation, view](const tutorial::Options&) {
    return std::make_unique<WorldScene>(simulation, view);
  };
}

void explain_step(Simulation& simulation, const RunOptions& o) {
  simulation.keep_reports();
  tutorial::Options options;
  options.explain_step = *o.explain;
  options.json = o.explain_json;
  tutorial::explain_scenes(lamina_info, options, {hand_over(simulation, render::Rect{})});
}

// Frames every `every` steps from step 0 by the harness; the steps after the last frame here.
void render_frames(Simulation& simulation, const RunOptions& o, const WorldSettings& settings,
                   long steps, ProgressBar& progress) {
  const render::Rect view = view_region(simulation.scene(), settings, steps);
  tutorial::Options options;
  options.out = *o.frames;
  options.frames = static_cast<int>(steps / o.every + 1);
  options.every = o.every;
  options.size = o.size;
  options.overlays = o.overlays;
  tutorial::render_scenes(lamina_info, options, {hand_over(simulation, view)});
  progress.finish();  // before the steps no frame shows, so the bar ends with the frames
  while (simulation.steps_taken() < steps) simulation.step();
}

void print_summary(const Simulation& simulation, const std::optional<TraceWriter>& trace) {
  std::cout << simulation.scene().name << ": " << simulation.steps_taken() << " steps, t = "
            << simulation.world().time() << " s";
  if (trace) {
    const char* separator = ", trace -> ";
    for (const std::filesystem::path& path : trace->paths()) {
      std::cout << separator << path.string();
      separator = ", ";
    }
  }
  std::cout << '\n';
}

}  // namespace

void run_scene(const RunOptions& o) {
  Scene scene = load_scene(o.scene);
  const WorldSettings settings = run_settings(o, scene);
  const long steps = o.steps.value_or(scene.steps);
  Simulation simulation(std::move(scene), settings, o.scene);
  if (o.explain) {
    explain_step(simulation, o);
    return;
  }
  std::optional<TraceWriter> trace;
  if (o.trace) simulation.record_to(trace.emplace(*o.trace));
  ProgressBar progress(simulation.scene().name, steps);
  simulation.show_progress(progress);
  if (o.frames) {
    render_frames(simulation, o, settings, steps, progress);
  } else {
    while (simulation.steps_taken() < steps) simulation.step();
  }
  progress.finish();
  if (trace) trace->finish();
  print_summary(simulation, trace);
}

}  // namespace lamina::cli
