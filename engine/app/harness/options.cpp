#include "app/harness/options.h"

#include <iostream>

#include <CLI/CLI.hpp>

namespace lamina::tutorial {

ParsedOptions parse_options(int argc, char** argv, const TutorialInfo& info) {
  CLI::App app(info.summary, info.name);
  Options o;
  o.render.out = "images/" + info.chapter;
  o.render.overlays = info.default_overlays;
  std::string format = "text";
  int frames = 0, every = 0;
  long explain = 0;
  app.add_option_function<std::string>(
         "--out", [&o](const std::string& folder) { o.render.out = folder; },
         "folder for the frames, CSV data and plots")
      ->default_str(o.render.out.string());
  auto* frames_option =
      app.add_option("--frames", frames, "frames per scene")->check(CLI::PositiveNumber);
  auto* every_option =
      app.add_option("--every", every, "time steps between frames")->check(CLI::PositiveNumber);
  add_render_options(app, o.render);
  auto* explain_option = app.add_option("--explain", explain,
                                        "print what the engine computed in step STEP (from "
                                        "t = STEP Δt), with equation numbers; renders nothing")
                             ->check(CLI::NonNegativeNumber);
  app.add_option("--explain-format", format, "text or json")
      ->capture_default_str()
      ->check(CLI::IsMember({"text", "json"}));
  app.add_flag("--step-through", o.step_through,
               "print every step in turn (Enter for the next, "
               "q to stop); renders nothing")
      ->excludes(explain_option);
  add_viewer_options(app, o.viewer, o.viewer_steps,
                     "write the step-through viewer of every scene into DIR: DIR/index.html, every "
                     "step of the frames' span with its phases, rows and sweeps (docs/viewer.md); "
                     "renders no frame sequence")
      ->excludes(explain_option);
  app.add_flag("--check-layout", o.render.check_layout,
               "paint every frame and check its layout, writing no frame: fail, naming them, when "
               "a legend, panel or label covers a body or another, a character has no font, or "
               "(with --lang ko) English is left (docs/slides.md)");
  if (info.has_cache) app.add_flag("--no-cache", o.no_cache, "solve without the contact cache");
  if (!info.solvers.empty()) {
    app.add_option_function<std::string>(
           "--solver", [&o](const std::string& name) { o.solver = name; },
           "the method: text (the text's own) or pgs (with Lamina's additions), as `lamina "
           "solvers` lists them (default: each scene's own)")
        ->type_name("NAME")
        ->check(CLI::IsMember(info.solvers));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help prints the help, exit 0; a bad option or value is one line and exit 2, as `lamina`
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return {std::nullopt, app.exit(e)};
    std::cerr << info.name << ": " << e.what() << '\n';
    return {std::nullopt, 2};
  }
  if (*frames_option) o.frames = frames;
  if (*every_option) o.every = every;
  if (*explain_option) o.explain_step = explain;
  o.json = format == "json";
  return {o, 0};
}

}  // namespace lamina::tutorial
