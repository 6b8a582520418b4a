#include "lamina/simulation.h"

#include "lamina/exit_codes.h"
#include "scene/scene_world.h"
#include "scene/trace.h"

namespace lamina::cli {

World checked_world(const Scene& scene, const WorldSettings& settings, const std::string& origin) {
  try {
    return build_world(scene, settings);
  } catch (const std::invalid_argument& e) {
    throw InputError(origin + ": " + e.what());
  }
}

Simulation::Simulation(Scene scene, const WorldSettings& settings, const std::string& origin)
    : scene_(std::move(scene)), world_(checked_world(scene_, settings, origin)) {}

void Simulation::step() {
  if (keep_reports_) {
    world_.step(report_);
  } else {
    world_.step();
  }
  ++steps_taken_;
  if (trace_ != nullptr) trace_->write(trace_step(scene_, world_, steps_taken_));
  if (progress_ != nullptr) progress_->advance();
}

}  // namespace lamina::cli
