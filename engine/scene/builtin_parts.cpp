#include "scene/builtin_parts.h"

#include <utility>

namespace lamina::builtin {

BodyDescription ground(double half_width) {
  BodyDescription g;
  g.name = "ground";
  g.shape.half_extents = {half_width, 0.5};
  g.position = {0.0, -0.5};
  g.is_static = true;
  return g;
}

BodyDescription box(const std::string& name, Vec2 position, Vec2 half_extents, double angle) {
  BodyDescription b;
  b.name = name;
  b.shape.half_extents = half_extents;
  b.position = position;
  b.angle = angle;
  return b;
}

Scene with(std::vector<BodyDescription> bodies, std::vector<JointDescription> joints) {
  Scene s;
  s.bodies = std::move(bodies);
  s.joints = std::move(joints);
  return s;
}

}  // namespace lamina::builtin
