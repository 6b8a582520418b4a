#include "scene/builtin_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

#include "language/language.h"
#include "scene/builtin_parts.h"
#include "scene/convex_scenes.h"
#include "scene/scene_json.h"
#include "scene/shortest_number.h"

namespace lamina {
namespace {

using namespace builtin;

JointDescription revolute(const std::string& a, const std::string& b, Vec2 anchor) {
  JointDescription j;
  j.type = JointType::revolute;
  j.bodies = {a, b};
  j.anchor = anchor;
  return j;
}

constexpr int pyramid_rows = 20;  // the boxes in the base of "pyramid"

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

// N unit boxes placed touching, one on another, on the ground.
Scene vertical_stack(double n) {
  std::vector<BodyDescription> bodies = {ground()};
  for (int i = 0; i < static_cast<int>(n); ++i) {
    bodies.push_back(box("box" + std::to_string(i), {0.0, half + 2 * half * i}));
  }
  return with(bodies);
}

// A unit box of density R resting on a unit box of density 1 on the ground: a mass ratio R.
Scene heavy_on_light(double ratio) {
  BodyDescription light = box("light", {0.0, half});
  BodyDescription heavy = box("heavy", {0.0, 3 * half});
  heavy.density = ratio;
  return with({ground(), light, heavy});
}

// Ten links (half extents 0.25 × 0.05, density 1, 0.05 kg each) pinned end to end from a fixed
// point at (0, 10), released horizontal, and a disc of radius 0.5 pinned by its rim at the last
// link's free end, whose mass is R times the chain's 0.5 kg.
Scene ball_and_chain(double ratio) {
  constexpr int links = 10;
  constexpr double link_length = 0.5, radius = 0.5, height = 10.0;
  BodyDescription anchor = box("anchor", {0.0, height}, {0.1, 0.1});
  anchor.is_static = true;
  std::vector<BodyDescription> bodies = {ground(), anchor};
  std::vector<JointDescription> joints;
  double chain_mass = 0.0;
  for (int i = 0; i < links; ++i) {
    const std::string name = "link" + std::to_string(i);
    bodies.push_back(box(name, {link_length * (i + 0.5), height}, {0.25, 0.05}));
    chain_mass += bodies.back().density * 0.5 * 0.1;
    joints.push_back(revolute(i == 0 ? "anchor" : "link" + std::to_string(i - 1), name,
                              {link_length * i, height}));
  }
  BodyDescription ball;
  ball.name = "ball";
  ball.shape.type = ShapeType::circle;
  ball.shape.radius = radius;
  ball.position = {link_length * links + radius, height};
  ball.density = ratio * chain_mass / (M_PI * radius * radius);
  bodies.push_back(ball);
  joints.push_back(revolute("link" + std::to_string(links - 1), "ball", {link_length * links, height}));
  return with(bodies, joints);
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
    bodies.push_back(box(name, {-4.5 + i, 3.0}, {0.5, 0.1}));  // from x = −5 + i to −4 + i
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
std::string pyramid_description(double n, Wording words) {
  const int rows = static_cast<int>(n);
  return fill(words(msg("a pyramid of {0} boxes placed touching, {1} in its base")),
              {std::to_string(rows * (rows + 1) / 2), std::to_string(rows)});
}

std::string stack_description(double n, Wording words) {
  return fill(words(msg("{0} boxes placed touching, one on another")), {std::to_string(static_cast<int>(n))});
}

std::string heavy_description(double ratio, Wording words) {
  return fill(words(msg("a box {0} times as dense resting on a unit box")), {shortest_number(ratio)});
}

std::string chain_description(double ratio, Wording words) {
  return fill(words(msg("ten links pinned from (0, 10), released level, with a ball {0} times the chain's mass")),
              {shortest_number(ratio)});
}

// A family of scenes `NAME:P`: what P is, its range and default, and how to build a member.
struct Family {
  std::string parameter;            // "N" or "R"
  std::string meaning;              // what P is, for `lamina scenes`
  bool whole;                       // P must be a whole number
  double low, high;                 // P's range
  double fallback;                  // the member `NAME` alone gives
  std::string (*describe)(double, Wording);  // a member's description
  Scene (*build)(double);           // a member but for its name and description
};

const std::map<std::string, Family>& families() {
  static const std::map<std::string, Family> table = {
      {"ball-and-chain", {"R", "the ball's mass over the chain's", false, 1e-3, 1e4, 100.0,
                          chain_description, ball_and_chain}},
      {"heavy-on-light", {"R", "the top box's density over the bottom box's", false, 1e-3, 1e4,
                          100.0, heavy_description, heavy_on_light}},
      {"hexagon-pyramid", {"N", "the hexagons in its base", true, 1.0, 1000.0, 10.0,
                           hexagon_pyramid_description, hexagon_pyramid}},
      {"pyramid", {"N", "the boxes in its base", true, 1.0, 1000.0, double(pyramid_rows),
                   pyramid_description, [](double n) { return pyramid_scene(static_cast<int>(n)); }}},
      {"vertical-stack", {"N", "the boxes", true, 1.0, 1000.0, 5.0, stack_description,
                          vertical_stack}},
  };
  return table;
}

// A built-in scene: its description, written here once, and how to build the rest of it.
struct Recipe {
  std::string description;  // one line for `lamina scenes`, and the built scene's description
  Scene (*build)();         // the scene but for its name and description
};

// Every built-in scene by name; the list reads it without building any scene.
const std::map<std::string, Recipe>& recipes() {
  static const std::map<std::string, Recipe> table = {
      {"box-on-ground", {msg("a box dropped flat from y = 2 onto the ground"),
                         [] { return box_on_ground(2.0, 0.0); }}},
      {"box-on-ground-tilted", {msg("a box dropped from y = 2 tilted by 0.3 rad (Fig 4-2..4-5)"),
                                [] { return box_on_ground(2.0, 0.3); }}},
      {"box-on-ground-resting", {msg("a box placed resting on the ground"),
                                 [] { return box_on_ground(half, 0.0); }}},
      {"incline", {msg("a box sliding on a frictionless 30° ramp, held up by contact"),
                   [] { return ramp(M_PI / 6, 0.0); }}},
      {"friction-ramp", {msg("a box on a 30° ramp with μ = 0.4 < tan 30°: it slides"),
                         [] { return ramp(M_PI / 6, 0.4); }}},
      {"pendulum", {msg("a disc on a 2 m rod, released horizontal (distance constraint)"), pendulum}},
      {"angle-limit", {msg("a pinned bar released level; an angle limit stops it 0.5 rad past hanging"),
                       angle_limit}},
      {"incline-constraint", {msg("a box held on a frictionless 30° line (Fig 3-1, incline constraint)"),
                              incline_constraint}},
      {"chain", {msg("eight links pinned end to end, released horizontal (revolute joints)"), chain}},
      {"dominoes", {msg("ten dominoes; the first is pushed over"), dominoes}},
      {"bridge", {msg("ten planks pinned end to end between two posts, a box dropped on them"), bridge}},
      {"see-saw", {msg("a plank pinned on a post; a box dropped on one end"), see_saw}},
      {"wedge-ramp", {msg("a hexagon tumbling down a 35° polygon wedge"), wedge_ramp}},
      {"capsule-pile", {msg("thirty capsules dropped in layers between two walls"), capsule_pile}},
  };
  return table;
}

}  // namespace

std::vector<BuiltinScene> builtin_scene_list() {
  std::vector<BuiltinScene> list;
  for (const auto& [name, recipe] : recipes()) list.push_back({name, recipe.description});
  for (const auto& [name, family] : families()) list.push_back({name, family.describe(family.fallback, as_written)});
  std::sort(list.begin(), list.end(),
            [](const BuiltinScene& a, const BuiltinScene& b) { return a.name < b.name; });
  return list;
}

std::vector<SceneFamily> builtin_scene_families() {
  std::vector<SceneFamily> list;
  for (const auto& [name, f] : families()) {
    list.push_back({name, f.parameter,
                    f.meaning + "; " + f.parameter + (f.whole ? " a whole number" : "") + " in [" +
                        shortest_number(f.low) + ", " + shortest_number(f.high) + "], default " +
                        shortest_number(f.fallback)});
  }
  return list;
}

namespace {

// A family's member by its name "NAME:P" (or "NAME", the default): the family and P. nullptr for
// a name of no family; throws SceneError for a P out of the family's range.
const Family* family_member(const std::string& name, double& p) {
  const std::string family_name = name.substr(0, name.find(':'));
  const auto family = families().find(family_name);
  if (family == families().end()) return nullptr;
  const Family& f = family->second;
  p = f.fallback;
  if (family_name != name) {
    const std::string text = name.substr(family_name.size() + 1);
    char* end = nullptr;
    p = std::strtod(text.c_str(), &end);
    const bool whole_ok = !f.whole || p == std::floor(p);
    if (text.empty() || *end != '\0' || !(p >= f.low && p <= f.high) || !whole_ok) {
      throw SceneError(name + ": " + f.parameter + " must be " +
                       (f.whole ? "a whole number" : "a number") + " in [" +
                       shortest_number(f.low) + ", " + shortest_number(f.high) + "]");
    }
  }
  return &f;
}

}  // namespace

Scene builtin_scene(const std::string& name) {
  const auto recipe = recipes().find(name);
  if (recipe != recipes().end()) {
    Scene scene = recipe->second.build();
    scene.name = recipe->first;
    scene.description = recipe->second.description;
    return scene;
  }
  double p = 0.0;
  const Family* f = family_member(name, p);
  if (f == nullptr) throw SceneError(name + ": no such built-in scene (see `lamina scenes`)");
  const std::string family_name = name.substr(0, name.find(':'));
  Scene scene = f->build(p);
  scene.name = p == f->fallback ? family_name : family_name + ":" + shortest_number(p);
  scene.description = f->describe(p, as_written);
  return scene;
}

std::string shown_description(const Scene& scene) {
  if (current_language() == Language::en) return scene.description;
  const auto recipe = recipes().find(scene.name);
  if (recipe != recipes().end()) {
    return scene.description == recipe->second.description ? tr(recipe->second.description.c_str())
                                                           : scene.description;
  }
  double p = 0.0;
  try {
    const Family* f = family_member(scene.name, p);
    if (f != nullptr && scene.description == f->describe(p, as_written)) return f->describe(p, tr);
  } catch (const SceneError&) {
    // a scene file's own name that looks like a family's member: its description as written
  }
  return scene.description;
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
  s.description = pyramid_description(rows, as_written);
  return s;
}

}  // namespace lamina
