#include "app/cli/command_line.h"

#include <iostream>

#include <CLI/CLI.hpp>

#include "app/harness/render_request.h"
#include "app/cli/exit_codes.h"
#include "beyond/methods.h"
#include "motion/pitfalls.h"
#include "scene/scene_limits.h"

namespace lamina::cli {
namespace {

// The ranges of a scene file's dt, iterations, beta and steps (scene_limits.h), as CLI11 checks.
template <typename T>
CLI::Range range_of(scene_limits::Range<T> range) {
  return CLI::Range(range.low, range.high);
}

const char* const exit_codes =
    "Exit codes: 0 ok; 2 bad input (a scene file, option value or output path: one line on "
    "standard error names it, and nothing is written); 1 internal failure (a bug, or no OpenGL "
    "for --frames); 3 the run diverged (a body's state is no longer finite: one line names the "
    "body and the step, the trace and frames hold every step before); 130 interrupted by Ctrl-C "
    "(143 by SIGTERM: the trace and frames hold every step taken).\n"
    "Documentation: docs/lamina-command.md, docs/scene-format.md.";

const char* const scene_help =
    "a scene file (JSON, see docs/scene-format.md), or the name of a built-in scene "
    "(`lamina scenes`; NAME:P sets a family's parameter, e.g. pyramid:10, heavy-on-light:1000)";


// Adds an option whose value goes into an std::optional when it is given.
template <typename T>
CLI::Option* add_optional(CLI::App& app, const std::string& name, std::optional<T>& target,
                          const std::string& help) {
  return app.add_option_function<T>(name, [&target](const T& value) { target = value; }, help);
}

void add_run_options(CLI::App& run, RunOptions& o, std::string& explain_format) {
  run.add_option("SCENE", o.scene, scene_help)->required();
  add_optional(run, "--steps", o.steps, "time steps to take (default: the scene's `steps`)")
      ->type_name("N")->check(range_of(scene_limits::steps));
  add_optional(run, "--dt", o.dt, "the time step Δt in s (default: the scene's `dt`)")
      ->type_name("S")->check(range_of(scene_limits::dt));
  add_optional(run, "--iterations", o.iterations, "PGS sweeps per step (default: the scene's)")
      ->type_name("K")->check(range_of(scene_limits::iterations));
  add_optional(run, "--beta", o.beta, "β of the position bias, eq. 3-14 and 4-4 (default: the scene's)")
      ->type_name("B")->check(range_of(scene_limits::beta));
  run.add_flag("--no-cache", o.no_cache, "solve without the contact cache (no warm start, Fig 4-2..4-5)");
  run.add_option("--threads", o.threads,
                 "threads that take each step: collision, the contact cache, the rows and the "
                 "integration split between them, PGS's sweeps a pipeline; the same state, trace "
                 "and frames bit for bit on any number, only faster up to the machine's cores "
                 "and for scenes of --threads-min-bodies bodies or more (docs/performance.md)")
      ->type_name("N")->check(CLI::Range(1, 64))->capture_default_str();
  run.add_option("--threads-min-bodies", o.threads_min_bodies,
                 "the bodies a scene needs before its steps are taken on --threads; a smaller "
                 "scene's steps are faster on one thread, with the same bits (0: always on "
                 "--threads)")
      ->type_name("N")->check(CLI::Range(0, 1000000000))->capture_default_str();
  run.add_flag("--allow-large", o.allow_large,
               "run a scene past the work limits (more than 5e7 body-steps, 1e5 overlapping pairs "
               "at t = 0, or 1e10 frame pixels: minutes of work; docs/lamina-command.md)");
  std::vector<std::string> solvers;
  for (const SolverInfo& s : method_list()) solvers.push_back(s.name);
  add_optional(run, "--solver", o.solver,
               "the method: text (the text's own), pgs (Lamina's additions to it), block, exact or "
               "islands (chapter 6, beyond the text); `lamina solvers` says what each does "
               "(default: the scene's `solver`, islands when it has none)")
      ->type_name("NAME")->check(CLI::IsMember(solvers));
  std::vector<std::string> pitfalls;
  for (const PitfallInfo& p : pitfall_list()) pitfalls.push_back(p.name);
  run.add_option("--pitfall", o.pitfalls,
                 "put back one classic mistake, to watch it break the scene (may be given more "
                 "than once): lambda-b1, no-renormalisation, clamp-increment, no-warm-start, "
                 "crude-friction, baumgarte-no-slop (docs/ch6-beyond-the-text.md)")
      ->type_name("NAME")->check(CLI::IsMember(pitfalls));
  auto* trace = add_optional(run, "--trace", o.trace,
                             "write every step to FILE: JSON Lines, or CSV when FILE ends in .csv "
                             "(contacts then go to FILE.contacts.csv)")->type_name("FILE");
  auto* frames = add_optional(run, "--frames", o.frames,
                              "render PNG frames into DIR: <scene>_0000.png shows step 0 (the state "
                              "at t = 0 and what step 0 solved), then one every --every steps")
                     ->type_name("DIR");
  auto* every = run.add_option("--every", o.every, "steps between frames (of --frames and --video)")
                    ->type_name("K")->capture_default_str()->check(CLI::PositiveNumber);
  auto* viewer = tutorial::add_viewer_options(
      run, o.viewer, o.viewer_steps,
      "write the step-through viewer into DIR: DIR/index.html shows every step, its phases, rows "
      "and sweeps, in a browser, from the file system (docs/viewer.md)");
  const std::vector<CLI::Option*> render_options = tutorial::add_render_options(run, o.render);
  // the frames' options shape the viewer's frames and the video too: each needs one of them
  run.callback([frames, viewer, every, render_options] {
    const CLI::Option* video = render_options.at(6);  // add_render_options' order
    if (every->count() > 0 && frames->count() == 0 && video->count() == 0) {
      throw CLI::ValidationError("--every needs --frames or --video");
    }
    if (frames->count() > 0 || viewer->count() > 0 || video->count() > 0) return;
    for (const CLI::Option* option : render_options) {
      if (option->count() > 0) {
        throw CLI::ValidationError(option->get_name() + " needs --frames, --viewer or --video");
      }
    }
  });
  auto* explain = add_optional(run, "--explain", o.explain, "print what the engine computed in "
                               "step STEP (from t = STEP Δt to t + Δt), with equation numbers, "
                               "and stop; writes no file")
                      ->type_name("STEP")->check(range_of(scene_limits::steps))
                      ->excludes(trace)->excludes(frames)->excludes(viewer);
  run.add_flag("--profile", o.profile,
               "after the run, print where the World's steps spent their time, phase by phase of "
               "the chapter-5 walk-through (wall clock, the steps after the first; "
               "docs/performance.md)")
      ->excludes(explain);
  run.add_option("--explain-format", explain_format, "text or json")
      ->type_name("FORMAT")->capture_default_str()->check(CLI::IsMember({"text", "json"}))->needs(explain);
}

// CLI11's message, or which subcommand was expected when none was given.
std::string parse_error_message(const CLI::App& app, const CLI::ParseError& e) {
  if (!app.get_subcommands().empty()) return e.what();
  const std::vector<std::string> rest = app.remaining();
  return (rest.empty() ? std::string("expected") : "'" + rest.front() + "' is not") +
         " a subcommand: run, scenes, solvers, show or check (see lamina --help)";
}

}  // namespace

ParsedCommand parse_command_line(int argc, char** argv) {
  CLI::App app("lamina: simulate Lamina scenes, write their traces and frames", "lamina");
  app.set_help_all_flag("--help-all", "print the help of every subcommand");
  app.footer(exit_codes);
  app.require_subcommand(1);
  Command c;
  std::string explain_format = "text";
  CLI::App* run = app.add_subcommand("run", "simulate a scene; write its trace, frames, or one step explained");
  add_run_options(*run, c.run, explain_format);
  CLI::App* scenes = app.add_subcommand("scenes", "list the built-in scenes with a line on each");
  CLI::App* solvers = app.add_subcommand("solvers", "list the solvers with what each departs from the text");
  CLI::App* show = app.add_subcommand("show", "print a scene as a JSON scene file, to copy and edit");
  show->add_option("SCENE", c.scene, scene_help)->required();
  CLI::App* check = app.add_subcommand("check", "validate a scene file; simulate nothing");
  check->add_option("SCENE", c.scene, scene_help)->required();
  for (CLI::App* sub : {run, scenes, solvers, show, check}) sub->footer(exit_codes);
  try {
    app.parse(argc, argv);
    c.run.explain_json = explain_format == "json";
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return {std::nullopt, app.exit(e)};
    std::cerr << "lamina: " << parse_error_message(app, e) << '\n';
    return {std::nullopt, exit_bad_input};
  }
  c.kind = *run ? Command::Kind::run : *scenes ? Command::Kind::scenes
         : *solvers ? Command::Kind::solvers : *show ? Command::Kind::show : Command::Kind::check;
  return {c, exit_ok};
}

}  // namespace lamina::cli
