// A scene being simulated by `lamina run`: its world, the steps taken, and where each step is
// recorded (the trace, the progress bar). Step k goes from t = k Δt to t + Δt.
#pragma once

#include <string>
#include <vector>

#include "app/cli/progress_bar.h"
#include "contact/world.h"
#include "scene/scene.h"
#include "trace/trace_writer.h"

namespace lamina::cli {

class Simulation {
 public:
  // The scene's world under `settings`. Throws InputError naming `origin` (the SCENE argument)
  // and the JSON path when the engine refuses a value of the scene.
  Simulation(Scene scene, const WorldSettings& settings, std::string origin);

  // From now on each step is written to `trace` and ticks `progress`.
  void record_to(TraceWriter& trace) { trace_ = &trace; }
  void show_progress(ProgressBar& progress) { progress_ = &progress; }

  // Takes step k = steps_taken(), then records it; with `report`, also what it solved. Throws
  // RunStopped, recording nothing of the step, when SIGINT or SIGTERM has asked the run to stop
  // (signals.h) or when the step left a body's state non-finite (exit_diverged): every step
  // recorded before it is complete.
  void step(WorldReport* report = nullptr);

  const Scene& scene() const { return scene_; }
  const World& world() const { return world_; }
  const std::string& origin() const { return origin_; }
  long steps_taken() const { return steps_taken_; }
  // The scene's body names, in the World's order.
  std::vector<std::string> body_names() const;

 private:
  void throw_if_diverged() const;

  Scene scene_;
  std::string origin_;                 // the SCENE argument, which messages name
  World world_;
  long steps_taken_ = 0;
  TraceWriter* trace_ = nullptr;       // where steps go, if anywhere
  TraceStep record_;                   // the step being written to trace_, refilled each step
  ProgressBar* progress_ = nullptr;    // the bar that counts steps, if any
};

// The settings the scene asks for (world_settings), and the world built from it, with the
// engine's refusals named after `origin` (InputError).
WorldSettings checked_settings(const Scene& scene, const std::string& origin);
World checked_world(const Scene& scene, const WorldSettings& settings, const std::string& origin);

}  // namespace lamina::cli
