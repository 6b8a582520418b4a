// The frames of a `lamina run`, recorded while the run is simulated (once), and the world region
// they show: fitted when the run is over, so every frame has the same scale. Frame k shows the
// state at t = k Δt with what step k solved from it (world_view.h).
//
// The region holds everything the dynamic bodies swept during the run, the parts of static
// bodies near it (the ground beneath, a ramp, a pivot) and a margin; with only static bodies,
// all of them; with no bodies, a few metres about the origin. A step whose bodies fly past
// what doubles can frame (~1e307 m) is left out, and so is every later one.
//
// Memory: a recorded frame keeps about 100 bytes per body and per contact (a 210-box pyramid:
// about 0.1 MB a frame), until the frames are rendered.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contact/world.h"
#include "render/camera.h"
#include "render/frame.h"

namespace lamina::cli {

struct RecordedFrame {
  long step = 0;        // k: the frame shows t = k Δt
  render::Frame frame;  // bodies at t, step k's contacts, the joints
};

class FrameRecording {
 public:
  // Starts from the world before its first step; a frame every `every` steps from step 0.
  FrameRecording(const World& world, int every, std::string caption);

  // Whether step k is drawn.
  bool draws(long step) const { return step % every_ == 0; }
  // Records the frame of step k, just taken by `world`; `at_t` are the bodies before it.
  void record(long step, const World& world, const std::vector<RigidBody>& at_t);
  // Adds the bodies' state after a step to the region swept.
  void sweep(const World& world);

  // The region every frame shows, fitted to what was swept.
  render::Rect view(const World& world) const;
  const std::vector<RecordedFrame>& frames() const { return frames_; }

 private:
  int every_;
  std::string caption_;
  std::optional<Aabb> swept_;         // the dynamic bodies' boxes so far, when any
  bool stopped_sweeping_ = false;     // a step went past what doubles frame
  std::vector<RecordedFrame> frames_;
};

}  // namespace lamina::cli
