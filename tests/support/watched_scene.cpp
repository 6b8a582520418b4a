#include "support/watched_scene.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/scene_json.h"
#include "scene/scene_world.h"
#include "world_energy.h"

namespace lamina {
namespace {

// What is wrong with a body's state after a step, or "" when nothing is.
std::string fault_of(const RigidBody& b) {
  if (!b.has_finite_state()) return "state is not finite";
  // Planar scenes stay exactly planar: no tolerance, the 3D core must not leak.
  if (b.x.z() != 0.0 || b.v.z() != 0.0 || b.angular_velocity.x() != 0.0 ||
      b.angular_velocity.y() != 0.0 || b.q.x() != 0.0 || b.q.y() != 0.0) {
    return "left the x–y plane";
  }
  return "";
}

}  // namespace

Watch::Watch(const Scene& s, const WorldSettings& settings)
    : scene(s), world(build_world(s, settings)), start_energy(mechanical_energy(world)),
      peak_energy(start_energy) {}

Watch::Watch(const Scene& s) : Watch(s, world_settings(s)) {}

bool Watch::run_for(double seconds) {
  const long steps = std::max(1L, std::lround(seconds / world.settings().step.dt));
  for (long k = 0; k < steps && fault.empty(); ++k) {
    world.step();
    ++steps_taken;
    inspect();
  }
  return fault.empty();
}

void Watch::inspect() {
  for (size_t i = 0; i < world.bodies().size(); ++i) {
    const RigidBody& b = world.bodies()[i];
    const std::string what = fault_of(b);
    if (!what.empty()) {
      fault = "step " + std::to_string(steps_taken) + ", body \"" + scene.bodies[i].name +
              "\": " + what;
      return;
    }
    if (b.is_static()) continue;
    top_speed = std::max(top_speed, b.v.norm());
  }
  peak_energy = std::max(peak_energy, mechanical_energy(world));
}

const RigidBody& Watch::body(const std::string& name) const {
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].name == name) return world.bodies()[i];
  }
  throw std::invalid_argument("no body " + name);
}

void require_sound(Watch& watch, double seconds) {
  const bool sound = watch.run_for(seconds);
  INFO(watch.fault);
  REQUIRE(sound);
}

BodyDescription box(const std::string& name, Vec2 position, Vec2 half_extents) {
  BodyDescription b;
  b.name = name;
  b.position = position;
  b.shape.half_extents = half_extents;
  return b;
}

BodyDescription circle(const std::string& name, Vec2 position, double radius) {
  BodyDescription b;
  b.name = name;
  b.position = position;
  b.shape.type = ShapeType::circle;
  b.shape.radius = radius;
  return b;
}

BodyDescription ground() {
  BodyDescription b = box("ground", {0.0, -0.5}, {20.0, 0.5});
  b.is_static = true;
  return b;
}

Scene stack(int count, double dt, int iterations) {
  Scene s;
  s.step.dt = dt;
  s.step.iterations = iterations;
  s.bodies = {ground()};
  for (int i = 0; i < count; ++i) {
    s.bodies.push_back(box("box" + std::to_string(i), {0.0, 0.5 + i}));
  }
  return s;
}

double slop_energy(const World& world) { return lift_energy(world, slop); }

std::string refusal(const Scene& scene) {
  try {
    parse_scene(scene_to_json(scene), "edited.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace lamina
