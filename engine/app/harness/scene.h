// A tutorial scene: a small simulation that steps, draws itself and explains its last step.
#pragma once

#include <filesystem>
#include <string>

#include "app/harness/explanation.h"
#include "app/harness/viewer.h"
#include "render/camera.h"
#include "render/frame.h"

namespace lamina::tutorial {

struct SceneInfo {
  std::string name;        // file prefix of its frames and data, e.g. "thrown_box"
  double time_step = 0.0;  // Δt, in s
  int frames = 1;          // frames to render by default
  int every = 1;           // steps between frames by default
  render::Rect view;       // the world region, in m, the camera fits once for all frames
};

class Scene {
 public:
  virtual ~Scene() = default;

  virtual SceneInfo info() const = 0;
  // Advances the simulation by one time step Δt.
  virtual void step() = 0;
  // Fills the frame from the current state (the harness adds the status line, t and the step,
  // unless the scene writes one of its own: an algorithm's iteration).
  virtual void draw(render::Frame& frame) const = 0;
  // What the engine computed in the last step (the initial state before the first).
  virtual Explanation explain() const = 0;
  // What the last step solved, for the step-through viewer: the bodies, rows, sweeps, contacts
  // and joints, and the explanation when the scene makes it here (else the harness adds
  // explain()); the harness adds the frame. Scenes without them add none.
  virtual void record(ViewerStep& /*step*/) const {}
  // Writes what the run recorded (CSV data, plots) into `folder` after the last frame.
  virtual void write_data(const std::filesystem::path& /*folder*/) const {}
};

}  // namespace lamina::tutorial
