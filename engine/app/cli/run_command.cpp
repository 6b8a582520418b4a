#include "app/cli/run_command.h"

#include <iostream>
#include <memory>

#include "app/cli/exit_codes.h"
#include "app/cli/frame_recording.h"
#include "app/cli/scene_source.h"
#include "app/cli/signals.h"
#include "app/cli/simulation.h"
#include "app/cli/work_limits.h"
#include "app/harness/format.h"
#include "language/language.h"
#include "app/harness/viewer.h"
#include "app/views/contact/world_explanation.h"
#include "motion/pitfalls.h"
#include "parallel/workers.h"
#include "render/utf8.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina::cli {
namespace {

WorldSettings run_settings(const RunOptions& o, Scene& scene) {
  if (o.solver) scene.solver = *o.solver;
  if (o.dt) scene.step.dt = *o.dt;
  if (o.iterations) scene.step.iterations = *o.iterations;
  if (o.beta) scene.step.beta = *o.beta;
  for (const std::string& name : o.pitfalls) scene.step.pitfalls.add(pitfall_named(name));
  WorldSettings settings = checked_settings(scene, o.scene);
  settings.cache.enabled = !o.no_cache;
  settings.threads = o.threads;
  settings.threads_min_bodies = o.threads_min_bodies;
  return settings;
}

// More threads than the machine's cores take the same steps, slower: a step's threads then
// wait for each other sleeping, and each piece of the step waits for a thread to be woken
// (docs/performance.md, "Two threads"). Said on stderr; the run goes on.
void note_threads_beyond_cores(int threads) {
  if (fits_cores(threads)) return;
  const int cores = machine_cores();
  std::cerr << "lamina: note: --threads " << threads << " on a machine of " << cores
            << " cores is slower than --threads " << cores << " (the same state bit for bit)\n";
}

// A World of fewer bodies than threads_min_bodies takes its steps on one thread, faster than on
// more (docs/performance.md, "Small worlds on one thread"). Said on stderr, so that a --threads
// that changes nothing is not taken for a measurement of threads.
void note_one_thread(const WorldSettings& settings, const World& world) {
  const std::size_t bodies = world.bodies().size();
  if (settings.threads < 2 || bodies >= static_cast<std::size_t>(settings.threads_min_bodies)) {
    return;
  }
  std::cerr << "lamina: note: the scene's " << bodies << " bodies are fewer than "
            << "--threads-min-bodies " << settings.threads_min_bodies
            << ": its steps are taken on one thread, which is faster (the same state bit for "
               "bit)\n";
}

// Steps 0 .. K − 1, then step K with its report, printed as the tutorials print theirs.
void explain_step(Simulation& simulation, long k, bool json) {
  while (simulation.steps_taken() < k) simulation.step();
  WorldReport report;
  simulation.step(&report);
  const tutorial::StepContext context{"lamina", simulation.scene().name, k, report.time,
                                      simulation.world().settings().step.dt};
  const tutorial::Explanation explanation =
      view::explain_world_step(simulation.world(), report, simulation.body_names());
  if (json) {
    std::cout << tutorial::to_json(context, explanation).dump(2) << '\n';
  } else {
    std::cout << tutorial::to_text(context, explanation);
  }
}

// The step-through viewer of a run (--viewer): its folder made before the first step, every
// step's record and frame, written as a page when the run is over.
struct ViewerRecording {
  tutorial::ViewerPage page;
  tutorial::ViewerRun run;
  FrameRecording frames;  // every step's frame, and the region they show

  ViewerRecording(const RunOptions& o, const Simulation& simulation, std::string caption)
      : page([&] {
          tutorial::RenderRequest request = o.render;
          request.out = *o.viewer;
          return request;
        }()),
        run("lamina", simulation.scene().name, simulation.world().settings().step.dt,
            tutorial::ViewerLimits{o.viewer_steps}),
        frames(simulation.world(), 1, std::move(caption)) {}
};

// The steps of the run, each recorded in the trace, every `every` steps as a frame, and in the
// viewer with what it solved.
void simulate(Simulation& simulation, long steps, FrameRecording* recording, ViewerRecording* viewer) {
  const std::vector<std::string> names = simulation.body_names();
  WorldReport report;
  while (simulation.steps_taken() < steps) {
    const long k = simulation.steps_taken();
    const bool draws = recording != nullptr && recording->draws(k);
    std::vector<RigidBody> at_t;
    if (draws || viewer != nullptr) at_t = simulation.world().bodies();
    simulation.step(viewer != nullptr ? &report : nullptr);
    if (draws) recording->record(k, simulation.world(), at_t);
    if (recording != nullptr) recording->sweep(simulation.world());
    if (viewer != nullptr) {
      viewer->frames.record(k, simulation.world(), at_t);
      viewer->frames.sweep(simulation.world());
      viewer->run.add(view::viewer_step(simulation.world(), report, names),
                      viewer->frames.frames().back().frame);
    }
  }
}

// Writes the viewer's page of the steps taken; SIGINT or SIGTERM stops it between two frames,
// leaving no page. Returns what it kept, e.g. "viewer -> out/index.html (rows and sweeps of
// steps 0..599)".
std::string write_viewer(ViewerRecording& viewer, const Simulation& simulation, const RunOptions& o) {
  viewer.run.fit(viewer.frames.view(simulation.world()));
  viewer.page.write({viewer.run}, [&] {
    if (const int signal = stop_signal()) {
      throw stopped_by(signal, simulation.origin(),
                       "after " + tutorial::counted(simulation.steps_taken(), "step", "steps") +
                           ", while writing the viewer");
    }
  });
  const std::optional<std::array<long, 2>> detailed = viewer.run.detailed();
  std::string kept = "viewer -> " + (*o.viewer / "index.html").string() + " (";
  kept += detailed ? "rows and sweeps of steps " + std::to_string((*detailed)[0]) + ".." +
                         std::to_string((*detailed)[1])
                   : std::string("no step's rows and sweeps");
  if (detailed && (*detailed)[1] + 1 < viewer.run.steps() && !o.viewer_steps) {
    kept += "; choose others with --viewer-steps A:B";
  }
  return kept + ")";
}

// The renderer of --frames: its folder made and an OpenGL context open before the first step,
// so that a folder that cannot be written, or no OpenGL, stops the run before it writes anything.
std::unique_ptr<tutorial::FrameRenderer> frame_renderer(const RunOptions& o) {
  if (!o.frames && !o.render.video) return nullptr;
  tutorial::RenderRequest request = o.render;
  request.out = o.frames.value_or(std::filesystem::path());
  request.write_frames = o.frames.has_value();  // --video alone: no frame files
  return std::make_unique<tutorial::FrameRenderer>(request);
}

// Renders the recorded frames, counting in `rendered` those written. SIGINT or SIGTERM stops it
// between two frames (RunStopped), the frames before complete.
void render_recording(const Simulation& simulation, const FrameRecording& recording,
                      tutorial::FrameRenderer& renderer, ProgressBar& progress, int& rendered) {
  std::size_t next = 0;
  rendered = 0;
  // the legend where no body goes in the whole run (docs/slides.md)
  const tutorial::FrameRenderer::LegendPlace place = renderer.place_legend(
      recording.frames().size(), [&](std::size_t k) -> const render::Frame& { return recording.frames()[k].frame; },
      recording.view(simulation.world()));
  try {
    renderer.render(tutorial::file_prefix(simulation.scene().name), place.view,
                    simulation.world().settings().step.dt, [&](render::Frame& frame, long& step) {
                      if (next == recording.frames().size()) return false;
                      if (const int signal = stop_signal()) {
                        throw stopped_by(signal, simulation.origin(),
                                         "after " + tutorial::counted(simulation.steps_taken(), "step", "steps") +
                                             ", while rendering frame " + std::to_string(next));
                      }
                      frame = recording.frames()[next].frame;
                      frame.legend_corner = place.corner;
                      step = recording.frames()[next++].step;
                      progress.advance();
                      return true;
                    });
  } catch (const RunStopped&) {
    renderer.finish();  // the frames queued before the stop, complete
    rendered = static_cast<int>(next);
    throw;
  }
  renderer.finish();
  rendered = static_cast<int>(next);
}

// "t.csv, t.contacts.csv"
std::string listed(const std::vector<std::filesystem::path>& paths) {
  std::string list;
  for (const std::filesystem::path& path : paths) list += (list.empty() ? "" : ", ") + path.string();
  return list;
}

// "steps 0..411", "no steps"
std::string step_span(long taken) {
  return taken > 0 ? "steps 0.." + std::to_string(taken - 1) : "no steps";
}

// "12 frames -> out"
// `video_whole`: the video was finished (a run stopped while rendering leaves none).
std::string frames_kept(int count, const RunOptions& o, bool video_whole = true) {
  std::string kept;
  if (o.frames) kept = tutorial::counted(count, "frame", "frames") + " -> " + o.frames->string();
  if (o.render.video) {
    kept += (kept.empty() ? "" : ", ") + (video_whole ? "video -> " + o.render.video->string() : std::string("no video"));
  }
  return kept;
}

void print_summary(const Simulation& simulation, const std::optional<TraceWriter>& trace,
                   const RunOptions& o, int frames, const std::string& viewer) {
  std::cout << simulation.scene().name << ": " << tutorial::counted(simulation.steps_taken(), "step", "steps") << ", t = "
            << simulation.world().time() << " s";
  if (trace) std::cout << ", trace -> " << listed(trace->paths());
  if (o.frames || o.render.video) std::cout << ", " << frames_kept(frames, o);
  if (!viewer.empty()) std::cout << ", " << viewer;
  std::cout << '\n';
}

// `text` and spaces after it to `width` characters (its code points, render/utf8.h), or with
// the spaces before it.
std::string padded(const std::string& text, std::size_t width, bool before = false) {
  const std::size_t characters = render::decode_utf8(text).size();
  const std::string spaces(width > characters ? width - characters : 0, ' ');
  return before ? spaces + text : text + spaces;
}

// --profile: each phase's wall-clock µs a step and share of the step, over the steps after the
// first (World::step_times_after_first), e.g. "  5–6. solve, F_c = Jᵀλ     101.5 µs  46.5 %".
void print_profile(const Simulation& simulation) {
  const StepTimes times = simulation.world().step_times_after_first();
  if (times.steps == 0) return;
  const long first = simulation.steps_taken() - times.steps;
  std::cout << simulation.scene().name << ": where the World's steps " << first << ".."
            << simulation.steps_taken() - 1 << " spent their time (wall clock, a step):\n";
  const double total = times.total();
  const auto line = [&](const std::string& name, double seconds) {
    const double us = 1e6 * seconds / static_cast<double>(times.steps);
    const double share = total > 0.0 ? 100.0 * seconds / total : 0.0;
    std::cout << "  " << padded(name, 24) << padded(tutorial::fixed(us, 1), 10, true) << " µs"
              << padded(tutorial::fixed(share, 1), 7, true) << " %\n";
  };
  for (int p = 0; p < step_phase_count; ++p) line(phase_name(StepPhase(p)), times.seconds[p]);
  line("whole step", total);
}

// What a run that stopped keeps, complete: "; trace -> t.jsonl holds steps 0..411, 103 frames
// -> out".
std::string kept_outputs(const Simulation& simulation, const RunOptions& o,
                         const std::optional<TraceWriter>& trace, const std::string& frames,
                         const std::string& viewer = "no viewer page") {
  std::string kept;
  if (trace) kept += "; trace -> " + listed(trace->paths()) + " holds " + step_span(simulation.steps_taken());
  if (o.frames || o.render.video) kept += (kept.empty() ? "; " : ", ") + frames;
  if (o.viewer) kept += (kept.empty() ? "; " : ", ") + viewer;
  return kept;
}

}  // namespace

void run_scene(const RunOptions& o) { run_scene(load_scene(o.scene), o); }

void run_scene(Scene scene, const RunOptions& o) {
  // the scene file's language, unless --lang said (the option set it as it was read)
  if (!o.render.language && !scene.lang.empty()) set_language(*language_named(scene.lang));
  const WorldSettings settings = run_settings(o, scene);
  note_threads_beyond_cores(settings.threads);
  const long steps = o.steps.value_or(scene.steps);
  if (!o.allow_large) {
    const long frames = o.explain ? 0
                                  : ((o.frames || o.render.video) ? (steps + o.every - 1) / o.every : 0) +
                                        (o.viewer ? steps : 0);
    check_work(scene, o.explain ? *o.explain + 1 : steps, frames, o.render.size, o.scene);
  }
  Simulation simulation(std::move(scene), settings, o.scene);
  note_one_thread(settings, simulation.world());
  note_stop_signals();
  if (o.explain) return explain_step(simulation, *o.explain, o.explain_json);
  const std::unique_ptr<tutorial::FrameRenderer> renderer = frame_renderer(o);
  std::optional<TraceWriter> trace;
  if (o.trace) simulation.record_to(trace.emplace(*o.trace));
  std::optional<FrameRecording> recording;
  const std::string description = shown_description(simulation.scene());
  const std::string& name = simulation.scene().name;
  std::string solver = fill(tr("solver: {0}"), {simulation.world().settings().solver});
  for (const PitfallInfo& p : pitfall_list()) {
    if (simulation.world().settings().step.pitfalls.has(p.pitfall)) solver += " · " + fill(tr("pitfall: {0}"), {p.name});
  }
  const std::string caption = (description.empty() ? name : name + " · " + description) + " · " + solver;
  if (o.frames || o.render.video) recording.emplace(simulation.world(), o.every, caption);
  std::optional<ViewerRecording> viewer;
  if (o.viewer) viewer.emplace(o, simulation, caption);
  const long frame_count = (recording ? (steps + o.every - 1) / o.every : 0) + (o.viewer ? steps : 0);
  ProgressBar progress(name, steps + frame_count);
  simulation.show_progress(progress);
  int frames = 0;
  try {
    simulate(simulation, steps, recording ? &*recording : nullptr, viewer ? &*viewer : nullptr);
  } catch (const RunStopped& stopped) {
    if (trace) trace->finish();  // the steps before the stop, complete
    std::string kept_frames = "no frames (stopped before rendering)";
    std::string kept_viewer = "no viewer page";
    // A run that diverged keeps the frames and the viewer of the steps before; a signal asked to
    // stop now.
    if (stopped.exit_code() == exit_diverged) {
      if (recording) {
        render_recording(simulation, *recording, *renderer, progress, frames);
        kept_frames = frames_kept(frames, o);
      }
      if (viewer && viewer->run.steps() > 0) kept_viewer = write_viewer(*viewer, simulation, o);
    }
    progress.finish();
    throw RunStopped(stopped.what() + kept_outputs(simulation, o, trace, kept_frames, kept_viewer),
                     stopped.exit_code());
  }
  if (trace) trace->finish();
  if (recording) {
    try {
      render_recording(simulation, *recording, *renderer, progress, frames);
    } catch (const RunStopped& stopped) {
      progress.finish();
      throw RunStopped(stopped.what() + kept_outputs(simulation, o, trace, frames_kept(frames, o, false)),
                       stopped.exit_code());
    }
  }
  std::string kept_viewer;
  if (viewer) {
    try {
      kept_viewer = write_viewer(*viewer, simulation, o);
    } catch (const RunStopped& stopped) {
      progress.finish();
      throw RunStopped(stopped.what() + kept_outputs(simulation, o, trace, frames_kept(frames, o)),
                       stopped.exit_code());
    }
  }
  progress.finish();
  print_summary(simulation, trace, o, frames, kept_viewer);
  if (o.profile) print_profile(simulation);
}

}  // namespace lamina::cli
