#include "scene/builtin_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

#include "scene/scene_json.h"

namespace lamina {
namespace {

constexpr double half = 0.5;  // half extent of the unit box, in m
constexpr int pyramid_rows = 20;  // the boxes in the base of "pyramid"

// The ground of every box-on-ground scene: a static box (20, 0.5) whose top is at y = 0.
BodyDescription ground(double half_width = 20.0) {
  BodyDescription g;
  g.name = "ground";
  g.shape.half_extents = {half_width, 0.5};
  g.position = {0.0, -0.5};
  g.is_static = true;
  return g;
}

BodyDescription box(const std::string& name, Vec2 position, Vec2 half_extents = {half, half},
                    double angle = 0.0) {
  BodyDescription b;
  b.name = name;
  b.shape.half_extents = half_extents;
  b.position = position;
  b.angle = angle;
  return b;
}

// A scene of these bodies and joints; builtin_scene gives it its name and description.
Scene with(std::vector<BodyDescription> bodies, std::vector<JointDescription> joints = {}) {
  Scene s;
  s.bodies = std::move(bodies);
  s.joints = std::move(joints);
  return s;
}

JointDescription revolute(const std::string& a, const std::string& b, Vec2 anchor) {
  JointDescription j;
  j.type = JointType::revolute;
  j.bodies = {a, b};
  j.anchor = anchor;
  return j;
}

Scene box_on_ground(double y, double angle) {
  return with({ground(), box("box", {0.0, y}, {half, half}, angle)});
}

// A static ramp tilted by θ (a rotated box) with a box resting on its slope.
Scene ramp(double theta, double friction) {
  BodyDescription slope = box("ramp", {0.0, 0.0}, {10.0, 0.5}, theta);
  slope.is_static = true;
  slope.friction = friction;
  const double lift = 0.5 + half;  // from the ramp's centre line to the box's centre
  BodyDescription block = box("box", {-lift * std::sin(theta), lift * std::cos(theta)}, {half, half}, theta);
  block.friction = friction;
  return with({slope, block});
}

Scene pendulum() {
  BodyDescription pivot = box("pivot", {0.0, 3.0}, {0.1, 0.1});
  pivot.is_static = true;
  BodyDescription bob;
  bob.name = "bob";
  bob.shape.type = ShapeType::circle;
  bob.shape.radius = 0.2;
  bob.position = {2.0, 3.0};
  JointDescription rod;
  rod.type = JointType::distance;
  rod.bodies = {"pivot", "bob"};
  rod.anchors = {Vec2{0.0, 3.0}, Vec2{2.0, 3.0}};
  return with({pivot, bob}, {rod});
}

// The chapter-3 tutorial's hinge (tutorials/ch3/angle_limit.cpp): a 1 kg bar, 1.2 m long, pinned
// at one end and released level (θ = 0); it may swing down to 0.5 rad past hanging, θ ≥ −π/2 − 0.5.
Scene angle_limit() {
  BodyDescription pivot = box("pivot", {0.0, 0.0}, {0.1, 0.1});
  pivot.is_static = true;
  BodyDescription bar = box("bar", {0.6, 0.0}, {0.6, 0.05});
  bar.density = 1.0 / 0.12;  // kg/m² over 0.12 m²: m = 1 kg
  JointDescription limit;
  limit.type = JointType::angle_limit;
  limit.bodies = {"pivot", "bar"};
  limit.lower = -M_PI / 2.0 - 0.5;
  return with({pivot, bar}, {revolute("pivot", "bar", {0.0, 0.0}), limit});
}

// The chapter-3 tutorial's incline (tutorials/ch3/incline_geometry.h): a 2 kg box whose centre an
// incline constraint holds on the line through p with normal N = (sin θ, cos θ), θ = 30°, half a
// box above the slope; released at rest 1 m down the line from p. The slope, a static box, lies
// 2 cm below the box so that no contact takes part (the contact cache keeps points only to 1 cm).
Scene incline_constraint() {
  const double theta = M_PI / 6.0;
  const Vec2 normal(0.5, std::sqrt(3.0) / 2.0);     // (sin θ, cos θ)
  const Vec2 downhill(std::sqrt(3.0) / 2.0, -0.5);  // (cos θ, −sin θ), along the line
  const Vec2 half_extents(0.4, 0.25);
  const Vec2 p = Vec2(0.0, 3.6) + half_extents.y() * normal;
  BodyDescription held = box("box", p + 1.0 * downhill, half_extents, -theta);
  held.density = 5.0;  // kg/m² over 0.4 m²: m = 2 kg
  const double gap = 0.02;  // from the box's bottom to the slope, in m
  const Vec2 slope_half(6.0, 0.25);
  const Vec2 slope_centre = p + 5.5 * downhill - (half_extents.y() + gap + slope_half.y()) * normal;
  BodyDescription slope = box("slope", slope_centre, slope_half, -theta);
  slope.is_static = true;
  JointDescription line;
  line.type = JointType::incline;
  line.body = "box";
  line.point = p;
  line.normal = normal;
  Scene s = with({slope, held}, {line});
  s.steps = 120;  // 2 s: the box slides 9.8 m, to the slope's lower end
  return s;
}

Scene chain() {
  std::vector<BodyDescription> bodies = {ground()};
  BodyDescription anchor = box("anchor", {0.0, 6.0}, {0.1, 0.1});
  anchor.is_static = true;
  bodies.push_back(anchor);
  std::vector<JointDescription> joints;
  const int links = 8;
  for (int i = 0; i < links; ++i) {
    const std::string name = "link" + std::to_string(i);
    bodies.push_back(box(name, {0.25 + 0.5 * i, 6.0}, {0.25, 0.05}));
    joints.push_back(revolute(i == 0 ? "anchor" : "link" + std::to_string(i - 1), name, {0.5 * i, 6.0}));
  }
  return with(bodies, joints);
}

Scene vertical_stack() {
  std::vector<BodyDescription> bodies = {ground()};
  for (int i = 0; i < 5; ++i) bodies.push_back(box("box" + std::to_string(i), {0.0, half + 2 * half * i}));
  return with(bodies);
}

Scene dominoes() {
  std::vector<BodyDescription> bodies = {ground()};
  for (int i = 0; i < 10; ++i) {
    bodies.push_back(box("domino" + std::to_string(i), {1.0 * i, 1.0}, {0.1, 1.0}));
  }
  bodies[1].angular_velocity = -1.5;
  return with(bodies);
}

Scene bridge() {
  std::vector<BodyDescription> bodies = {ground()};
  for (int side = 0; side < 2; ++side) {
    BodyDescription post = box(side == 0 ? "left-post" : "right-post", {side == 0 ? -5.5 : 5.5, 1.5}, {0.5, 1.5});
    post.is_static = true;
    bodies.push_back(post);
  }
  std::vector<JointDescription> joints;
  const int planks = 10;
  std::string previous = "left-post";
  for (int i = 0; i < planks; ++i) {
    const std::string name = "plank" + std::to_string(i);
    bodies.push_back(box(name, {-4.5 + i + 0.5, 3.0}, {0.5, 0.1}));
    joints.push_back(revolute(previous, name, {-5.0 + i, 3.0}));
    previous = name;
  }
  joints.push_back(revolute(previous, "right-post", {5.0, 3.0}));
  bodies.push_back(box("load", {0.0, 4.0}));
  return with(bodies, joints);
}

Scene see_saw() {
  BodyDescription base = box("base", {0.0, 0.5}, {0.2, 0.5});
  base.is_static = true;
  BodyDescription plank = box("plank", {0.0, 1.1}, {3.0, 0.1});
  BodyDescription weight = box("weight", {-2.5, 3.0});
  return with({ground(), base, plank, box("counterweight", {2.5, 1.7}, {0.25, 0.25}), weight},
              {revolute("base", "plank", {0.0, 1.1})});
}

// What a pyramid of `rows` rows is, written once for the list and for every pyramid:N.
std::string pyramid_description(int rows) {
  return "a pyramid of " + std::to_string(rows * (rows + 1) / 2) + " boxes placed touching, " +
         std::to_string(rows) + " in its base";
}

// A built-in scene: its description, written here once, and how to build the rest of it.
struct Recipe {
  std::string description;  // one line for `lamina scenes`, and the built scene's description
  Scene (*build)();         // the scene but for its name and description
};

// Every built-in scene by name; the list reads it without building any scene.
const std::map<std::string, Recipe>& recipes() {
  static const std::map<std::string, Recipe> table = {
      {"box-on-ground", {"a box dropped flat from y = 2 onto the ground",
                         [] { return box_on_ground(2.0, 0.0); }}},
      {"box-on-ground-tilted", {"a box dropped from y = 2 tilted by 0.3 rad (Fig 4-2..4-5)",
                                [] { return box_on_ground(2.0, 0.3); }}},
      {"box-on-ground-resting", {"a box placed resting on the ground",
                                 [] { return box_on_ground(half, 0.0); }}},
      {"incline", {"a box sliding on a frictionless 30° ramp, held up by contact",
                   [] { return ramp(M_PI / 6, 0.0); }}},
      {"friction-ramp", {"a box on a 30° ramp with μ = 0.4 < tan 30°: it slides",
                         [] { return ramp(M_PI / 6, 0.4); }}},
      {"pendulum", {"a disc on a 2 m rod, released horizontal (distance constraint)", pendulum}},
      {"angle-limit", {"a pinned bar released level; an angle limit stops it 0.5 rad past hanging",
                       angle_limit}},
      {"incline-constraint", {"a box held on a frictionless 30° line (Fig 3-1, incline constraint)",
                              incline_constraint}},
      {"chain", {"eight links pinned end to end, released horizontal (revolute joints)", chain}},
      {"vertical-stack", {"five boxes placed touching, one on another", vertical_stack}},
      {"pyramid", {pyramid_description(pyramid_rows), [] { return pyramid_scene(pyramid_rows); }}},
      {"dominoes", {"ten dominoes; the first is pushed over", dominoes}},
      {"bridge", {"ten planks pinned end to end between two posts, a box dropped on them", bridge}},
      {"see-saw", {"a plank pinned on a post; a box dropped on one end", see_saw}},
  };
  return table;
}

}  // namespace

std::vector<BuiltinScene> builtin_scene_list() {
  std::vector<BuiltinScene> list;
  for (const auto& [name, recipe] : recipes()) list.push_back({name, recipe.description});
  return list;
}

Scene builtin_scene(const std::string& name) {
  const std::string prefix = "pyramid:";
  if (name.rfind(prefix, 0) == 0) {
    const std::string rows = name.substr(prefix.size());
    char* end = nullptr;
    const long n = std::strtol(rows.c_str(), &end, 10);
    if (rows.empty() || *end != '\0' || n < 1 || n > 1000) {
      throw SceneError(name + ": pyramid rows must be a whole number in [1, 1000]");
    }
    return pyramid_scene(static_cast<int>(n));
  }
  const auto it = recipes().find(name);
  if (it == recipes().end()) {
    throw SceneError(name + ": no such built-in scene (see `lamina scenes`)");
  }
  Scene scene = it->second.build();
  scene.name = it->first;
  scene.description = it->second.description;
  return scene;
}

Scene pyramid_scene(int rows) {
  std::vector<BodyDescription> bodies = {ground(std::max(20.0, rows * half + 5.0))};
  for (int row = 0; row < rows; ++row) {
    const int count = rows - row;
    for (int i = 0; i < count; ++i) {
      const double x = (i - 0.5 * (count - 1)) * 2 * half;
      bodies.push_back(box("r" + std::to_string(row) + "b" + std::to_string(i), {x, half + 2 * half * row}));
    }
  }
  Scene s = with(bodies);
  s.name = rows == pyramid_rows ? "pyramid" : "pyramid:" + std::to_string(rows);
  s.description = pyramid_description(rows);
  return s;
}

}  // namespace lamina
