// A simulation as the tutorial harness sees a scene (harness/scene.h), so that `lamina run`
// renders frames and explains steps with the harness's own runs (harness/runs.h).
#pragma once

#include <vector>

#include "harness/scene.h"
#include "lamina/simulation.h"
#include "lamina/world_frame.h"

namespace lamina::cli {

class WorldScene : public tutorial::Scene {
 public:
  // `simulation` must not have stepped yet (the joints are read off its first pose) and must
  // outlive this. `view` is the world region every frame shows.
  WorldScene(Simulation& simulation, const render::Rect& view);

  tutorial::SceneInfo info() const override;
  void step() override { simulation_.step(); }
  void draw(render::Frame& frame) const override;
  tutorial::Explanation explain() const override;

 private:
  Simulation& simulation_;
  render::Rect view_;               // in m
  std::vector<JointEnds> joints_;   // the joints' ends on their bodies
};

// The scene's name as a file name prefix: anything but letters, digits, '.', '_' and '-'
// becomes '-' ("pyramid:5" → "pyramid-5"); an empty name is "scene".
std::string file_prefix(const std::string& name);

}  // namespace lamina::cli
