#include "app/cli/simulation.h"

#include "app/cli/exit_codes.h"
#include "app/cli/signals.h"
#include "app/harness/format.h"
#include "scene/scene_world.h"
#include "scene/shortest_number.h"
#include "trace/trace.h"

namespace lamina::cli {
namespace {

// "(x = (nan, 0.5), θ = 0.1, v = (inf, -2.0), ω = 0.0)": the planar state, as in a trace.
std::string planar_state(const RigidBody& body) {
  std::string text = "(x = (";
  append_shortest(text, body.x.x());
  text += ", ";
  append_shortest(text, body.x.y());
  text += "), θ = ";
  append_shortest(text, planar_angle(body.q));
  text += ", v = (";
  append_shortest(text, body.v.x());
  text += ", ";
  append_shortest(text, body.v.y());
  text += "), ω = ";
  append_shortest(text, body.angular_velocity.z());
  return text + ")";
}

}  // namespace

WorldSettings checked_settings(const Scene& scene, const std::string& origin) {
  try {
    return world_settings(scene);
  } catch (const std::invalid_argument& e) {
    throw InputError(origin + ": " + e.what());
  }
}

World checked_world(const Scene& scene, const WorldSettings& settings, const std::string& origin) {
  try {
    return build_world(scene, settings);
  } catch (const std::invalid_argument& e) {
    throw InputError(origin + ": " + e.what());
  }
}

Simulation::Simulation(Scene scene, const WorldSettings& settings, std::string origin)
    : scene_(std::move(scene)),
      origin_(std::move(origin)),
      world_(checked_world(scene_, settings, origin_)) {}

std::vector<std::string> Simulation::body_names() const {
  std::vector<std::string> names;
  for (const BodyDescription& body : scene_.bodies) names.push_back(body.name);
  return names;
}

void Simulation::step(WorldReport* report) {
  if (const int signal = stop_signal()) {
    throw stopped_by(signal, origin_, "after " + tutorial::counted(steps_taken_, "step", "steps"));
  }
  if (report != nullptr) {
    world_.step(*report);
  } else {
    world_.step();
  }
  throw_if_diverged();
  if (trace_ != nullptr) {
    trace_step(scene_, world_, steps_taken_, record_);
    trace_->write(record_);
  }
  ++steps_taken_;
  if (progress_ != nullptr) progress_->advance();
}

void Simulation::throw_if_diverged() const {
  const std::optional<std::size_t> body = world_.first_non_finite_body();
  if (!body) return;
  throw RunStopped(origin_ + ": step " + std::to_string(steps_taken_) + ": body \"" +
                       scene_.bodies[*body].name + "\" is no longer finite " +
                       planar_state(world_.bodies()[*body]),
                   exit_diverged);
}

}  // namespace lamina::cli
