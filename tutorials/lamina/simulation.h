// A scene being simulated by `lamina run`: its world, the steps taken, and where each step is
// recorded (the trace, the progress bar, the report --explain prints).
#pragma once

#include <string>

#include "contact/world.h"
#include "lamina/progress_bar.h"
#include "scene/scene.h"
#include "scene/trace_writer.h"

namespace lamina::cli {

class Simulation {
 public:
  // The scene's world under `settings`. Throws InputError naming `origin` (the SCENE argument)
  // when the engine refuses a value of the scene.
  Simulation(Scene scene, const WorldSettings& settings, std::string origin);

  // From now on each step is written to `trace`, ticks `progress`, or keeps its WorldReport.
  void record_to(TraceWriter& trace) { trace_ = &trace; }
  void show_progress(ProgressBar& progress) { progress_ = &progress; }
  void keep_reports() { keep_reports_ = true; }

  // t → t + Δt, then records the step. Throws RunStopped, recording nothing of the step, when
  // SIGINT or SIGTERM has asked the run to stop (signals.h) or when the step left a body's
  // state non-finite (exit_diverged): every step recorded before it is complete.
  void step();

  const Scene& scene() const { return scene_; }
  const World& world() const { return world_; }
  const std::string& origin() const { return origin_; }
  long steps_taken() const { return steps_taken_; }
  // What the last step solved; empty unless keep_reports() was called.
  const WorldReport& last_report() const { return report_; }

 private:
  void throw_if_diverged() const;

  Scene scene_;
  std::string origin_;                 // the SCENE argument, which messages name
  World world_;
  long steps_taken_ = 0;
  TraceWriter* trace_ = nullptr;       // where steps go, if anywhere
  ProgressBar* progress_ = nullptr;    // the bar that counts steps, if any
  bool keep_reports_ = false;          // step with a WorldReport (for --explain)
  WorldReport report_;                 // the last step's, when kept
};

// The world built from the scene, with the engine's refusals named after `origin`.
World checked_world(const Scene& scene, const WorldSettings& settings, const std::string& origin);

}  // namespace lamina::cli
