// A World stepped one step at a time with a record of each step, for tutorials that show and
// explain every step they take. Step k goes from t = k Δt to t + Δt; after it, report().bodies
// holds the bodies at t and world() holds them at t + Δt.
#pragma once

#include "contact/world.h"

namespace lamina::view {

class SteppedWorld {
 public:
  explicit SteppedWorld(World world) : world_(std::move(world)) {}

  // Takes the next step, k = step_index() + 1, recording what it solved.
  void step() {
    world_.step(report_);
    ++step_index_;
  }

  long step_index() const { return step_index_; }        // k of the last step, −1 before any
  const World& world() const { return world_; }          // at t + Δt
  const WorldReport& report() const { return report_; }  // what step k solved, from t
  const std::vector<RigidBody>& bodies_at_t() const { return report_.bodies; }

 private:
  World world_;
  WorldReport report_;
  long step_index_ = -1;
};

}  // namespace lamina::view
