#include "lamina/run_command.h"

#include <iostream>

#include "harness/runs.h"
#include "lamina/exit_codes.h"
#include "lamina/scene_source.h"
#include "lamina/signals.h"
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

// Frames every `every` steps from step 0 by the harness, of the region `view`.
void render_frames(Simulation& simulation, const RunOptions& o, const render::Rect& view,
                   long steps) {
  tutorial::Options options;
  options.out = *o.frames;
  options.frames = static_cast<int>(steps / o.every + 1);
  options.every = o.every;
  options.size = o.size;
  options.overlays = o.overlays;
  tutorial::render_scenes(lamina_info, options, {hand_over(simulation, view)});
}

// "t.csv, t.contacts.csv"
std::string listed(const std::vector<std::filesystem::path>& paths) {
  std::string list;
  for (const std::filesystem::path& path : paths) list += (list.empty() ? "" : ", ") + path.string();
  return list;
}

void print_summary(const Simulation& simulation, const std::optional<TraceWriter>& trace) {
  std::cout << simulation.scene().name << ": " << simulation.steps_taken() << " steps, t = "
            << simulation.world().time() << " s";
  if (trace) std::cout << ", trace -> " << listed(trace->paths());
  std::cout << '\n';
}

// What a run that stopped keeps, complete: "; trace -> t.jsonl holds steps 1..412, 207 frames
// -> out" (the frames of step 0 and every `every` steps up to the last step taken).
std::string kept_outputs(const Simulation& simulation, const RunOptions& o,
                         const std::optional<TraceWriter>& trace) {
  const long taken = simulation.steps_taken();
  std::string kept;
  if (trace) {
    kept += "; trace -> " + listed(trace->paths()) +
            (taken > 0 ? " holds steps 1.." + std::to_string(taken) : " holds no steps");
  }
  if (o.frames) {
    const long frames = taken / o.every + 1;
    kept += (trace ? ", " : "; ") + std::to_string(frames) +
            (frames == 1 ? " frame -> " : " frames -> ") + o.frames->string();
  }
  return kept;
}

}  // namespace

void run_scene(const RunOptions& o) { run_scene(load_scene(o.scene), o); }

void run_scene(Scene scene, const RunOptions& o) {
  const WorldSettings settings = run_settings(o, scene);
  const long steps = o.steps.value_or(scene.steps);
  Simulation simulation(std::move(scene), settings, o.scene);
  note_stop_signals();
  if (o.explain) {
    explain_step(simulation, o);
    return;
  }
  std::optional<TraceWriter> trace;
  if (o.trace) simulation.record_to(trace.emplace(*o.trace));
  std::optional<render::Rect> view;
  if (o.frames) view = view_region(simulation, steps);
  ProgressBar progress(simulation.scene().name, steps);
  simulation.show_progress(progress);
  try {
    if (view) {
      render_frames(simulation, o, *view, steps);
      progress.finish();  // before the steps no frame shows, so the bar ends with the frames
    }
    while (simulation.steps_taken() < steps) simulation.step();
  } catch (const RunStopped& stopped) {
    progress.finish();
    if (trace) trace->finish();  // the steps before the stop, complete
    throw RunStopped(stopped.what() + kept_outputs(simulation, o, trace), stopped.exit_code());
  }
  progress.finish();
  if (trace) trace->finish();
  print_summary(simulation, trace);
}

}  // namespace lamina::cli
