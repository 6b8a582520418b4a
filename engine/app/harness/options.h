// The options every chapter tutorial takes (CLI11).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/harness/render_request.h"
#include "render/overlay.h"

namespace lamina::tutorial {

// What a tutorial is, as its options and messages name it.
struct TutorialInfo {
  std::string name;                   // the executable, e.g. "02_unconstrained_motion"
  std::string chapter;                // e.g. "ch2": frames go to images/ch2/ by default
  std::string summary;                // one line for --help
  render::Overlays default_overlays;  // --overlay when not given
  bool has_cache = false;             // offers --no-cache (chapters with a contact cache)
  std::vector<std::string> solvers = {};  // offers --solver NAME with these (chapters with a World)
};

struct Options {
  RenderRequest render;              // --out (the folder for frames, CSV and plots), --size,
                                     // --overlay, --backend
  std::optional<int> frames;         // --frames: frames per scene (scene default when empty)
  std::optional<int> every;          // --every: steps between frames (scene default when empty)
  std::optional<long> explain_step;  // --explain STEP: print that step, render nothing
  bool json = false;                 // --explain-format json
  bool step_through = false;         // --step-through: print every step, render nothing
  bool no_cache = false;             // --no-cache (only where has_cache)
  std::optional<std::string> solver; // --solver NAME (only where solvers are offered)
  std::optional<std::filesystem::path> viewer;      // --viewer DIR: the step-through page
  std::optional<std::array<long, 2>> viewer_steps;  // --viewer-steps A:B
};

// The parsed options, or the exit code when parsing ended the run (--help, a bad option; CLI11
// has printed the message).
struct ParsedOptions {
  std::optional<Options> options;
  int exit_code = 0;
};

ParsedOptions parse_options(int argc, char** argv, const TutorialInfo& info);

}  // namespace lamina::tutorial
