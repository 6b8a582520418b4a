// `lamina run SCENE`: simulate a scene once, and write its trace, its frames, or one step
// explained. Step k goes from t = k Δt to t + Δt; trace line k records it, frame k shows the
// state at t with what step k solved, and --explain k explains it.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/harness/render_request.h"
#include "contact/world.h"
#include "scene/scene.h"

namespace lamina::cli {

struct RunOptions {
  std::string scene;                            // SCENE: a file or a built-in name
  std::optional<long> steps;                    // --steps (else the scene's `steps`)
  std::optional<double> dt;                     // --dt, in s (else the scene's)
  std::optional<int> iterations;                // --iterations (else the scene's)
  std::optional<double> beta;                   // --beta (else the scene's)
  std::optional<std::string> solver;            // --solver NAME (else the scene's)
  std::vector<std::string> pitfalls;            // --pitfall NAME, each (motion/pitfalls.h)
  bool no_cache = false;                        // --no-cache
  bool profile = false;                         // --profile
  int threads = 1;                              // --threads N: threads per step, same bits
  int threads_min_bodies = WorldSettings().threads_min_bodies;  // --threads-min-bodies N
  std::optional<std::filesystem::path> trace;   // --trace FILE
  std::optional<std::filesystem::path> frames;  // --frames DIR
  int every = 1;                                // --every K: steps between frames
  tutorial::RenderRequest render{{}, {1280, 720}, render::Overlays{render::Overlay::contacts}};
                                                // --size, --overlay, --backend (out: --frames)
  std::optional<std::filesystem::path> viewer;  // --viewer DIR
  std::optional<std::array<long, 2>> viewer_steps;  // --viewer-steps A:B
  std::optional<long> explain;                  // --explain STEP
  bool explain_json = false;                    // --explain-format json
  bool allow_large = false;                     // --allow-large: lift work_limits.h's limits
};

// Runs it; prints one summary line on standard output (--explain: the step instead).
// Throws SceneError, InputError or OutputError for bad input, having written nothing, and
// RunStopped when the run diverges or SIGINT/SIGTERM stops it, having put the trace of the
// steps before in place (its message says what was kept).
void run_scene(const RunOptions& options);
// The same with options.scene already loaded as `scene` (messages still name options.scene):
// tests run scenes through it that no scene file may hold.
void run_scene(Scene scene, const RunOptions& options);

}  // namespace lamina::cli
