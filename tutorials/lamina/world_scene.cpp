#include "lamina/world_scene.h"

#include <cctype>

#include "lamina/world_explanation.h"

namespace lamina::cli {

WorldScene::WorldScene(Simulation& simulation, const render::Rect& view)
    : simulation_(simulation),
      view_(view),
      joints_(joint_ends(simulation.scene(), simulation.world())) {}

tutorial::SceneInfo WorldScene::info() const {
  return {file_prefix(simulation_.scene().name), simulation_.world().settings().dt, 1, 1, view_};
}

void WorldScene::draw(render::Frame& frame) const {
  frame = world_frame(simulation_.scene(), simulation_.world(), joints_);
}

tutorial::Explanation WorldScene::explain() const {
  return world_explanation(simulation_.scene(), simulation_.world(), simulation_.last_report());
}

std::string file_prefix(const std::string& name) {
  std::string prefix = name;
  for (char& c : prefix) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
    if (!plain) c = '-';
  }
  return prefix.empty() ? "scene" : prefix;
}

}  // namespace lamina::cli
