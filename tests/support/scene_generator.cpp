#include "support/scene_generator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "beyond/methods.h"
#include "contact/shape.h"
#include "kinematics/mass_properties.h"
#include "scene/scene_json.h"
#include "scene/scene_limits.h"

namespace lamina::fuzz {

std::uint8_t Bytes::byte() { return next_ < size_ ? data_[next_++] : 0; }

int Bytes::integer(int low, int high) {
  const int span = high - low + 1;
  const int raw = (byte() << 8) | byte();
  return low + raw % span;
}

double Bytes::number(double low, double high) {
  const int raw = (byte() << 8) | byte();
  return low + (high - low) * raw / 65535.0;
}

double Bytes::log_number(double low, double high) {
  // exp(log(x)) may round just past an end (1e-5 becomes 9.999999999999997e-06)
  return std::clamp(std::exp(number(std::log(low), std::log(high))), low, high);
}

const char* kind_name(SceneKind kind) {
  switch (kind) {
    case SceneKind::general: return "general";
    case SceneKind::resting: return "resting";
    case SceneKind::island: return "island";
    case SceneKind::wide: return "wide";
  }
  return "?";
}

namespace {

// The step sizes and sweeps a generated scene may ask for: a lecture's range, not the reader's
// extremes (tests/test_extreme_scenes.cpp and the loader fuzzer cover those).
constexpr double step_sizes[] = {1.0 / 60, 1.0 / 120, 1.0 / 30, 1.0 / 240};

BodyDescription ground() {
  BodyDescription g;
  g.name = "ground";
  g.shape.half_extents = {20.0, 0.5};
  g.position = {0.0, -0.5};
  g.is_static = true;
  return g;
}

// A convex polygon: 3 to 8 points on an ellipse at increasing angles (any such set is convex
// and counter-clockwise), given about an offset origin, since scene files may do so. The gaps
// between the angles are at least a third of the mean gap, so that no three points are nearly
// on one line; a polygon the reader would still refuse (too small) becomes a triangle.
ShapeDescription polygon(Bytes& b) {
  ShapeDescription shape;
  shape.type = ShapeType::polygon;
  const int k = b.integer(3, Convex::max_vertices);
  const double a = b.number(0.15, 1.0), c = b.number(0.15, 1.0);
  std::vector<double> gaps;
  double total = 0.0;
  for (int i = 0; i < k; ++i) total += gaps.emplace_back(b.number(1.0, 3.0));
  const Vec2 origin(b.number(-0.5, 0.5), b.number(-0.5, 0.5));
  double angle = b.number(0.0, 2.0 * M_PI);
  for (int i = 0; i < k; ++i) {
    shape.vertices.push_back(Vec2(a * std::cos(angle), c * std::sin(angle)) - origin);
    angle += 2.0 * M_PI * gaps[i] / total;
  }
  if (polygon_problem(shape.vertices) ||
      polygon_moments(shape.vertices).area < scene_limits::polygon_area) {
    shape.vertices = {{-0.3, -0.2}, {0.3, -0.2}, {0.0, 0.3}};
  }
  return shape;
}

ShapeDescription any_shape(Bytes& b) {
  ShapeDescription shape;
  switch (b.integer(0, 3)) {
    case 0:
      shape.type = ShapeType::box;
      shape.half_extents = {b.number(0.1, 1.0), b.number(0.1, 1.0)};
      break;
    case 1:
      shape.type = ShapeType::circle;
      shape.radius = b.number(0.1, 0.8);
      break;
    case 2:
      shape = polygon(b);
      break;
    default:
      shape.type = ShapeType::capsule;
      shape.radius = b.number(0.08, 0.5);
      shape.length = b.number(scene_limits::capsule_length.low, 1.5);
      break;
  }
  return shape;
}

void choose_method(Bytes& b, Scene& scene) {
  const std::vector<SolverInfo>& methods = method_list();
  scene.solver = methods[b.integer(0, static_cast<int>(methods.size()) - 1)].name;
  scene.step.dt = step_sizes[b.integer(0, 3)];
  scene.step.iterations = b.integer(4, 30);
}

// A body placed resting on the ground (top at y = 0) on a flat side, at rest: a box on a face,
// a circle, a capsule lying down, a polygon on the edge nearest its centroid (the foot of the
// centroid on that edge's line lies inside it, so the polygon stands; one whose foot lies within
// a tenth of the edge of a corner becomes a box, which stands with room).
BodyDescription resting_body(Bytes& b, RestingFace* face = nullptr) {
  RestingFace unused;
  RestingFace& on = face ? *face : unused;
  BodyDescription body;
  body.name = "resting";
  body.shape = any_shape(b);
  body.density = b.number(0.3, 3.0);
  body.friction = b.number(0.2, 1.0);
  const ShapeDescription& s = body.shape;
  if (s.type == ShapeType::box) {
    body.position = {0.0, s.half_extents.y()};
    on = {2.0 * s.half_extents.x(), s.half_extents.y()};
  } else if (s.type != ShapeType::polygon) {
    body.position = {0.0, s.radius};
    on = {s.type == ShapeType::capsule ? s.length : 0.0, s.radius};
  } else {
    const AreaMoments m = polygon_moments(s.vertices);
    const int n = static_cast<int>(s.vertices.size());
    int nearest = 0;
    double nearest_distance = 1e300;
    for (int i = 0; i < n; ++i) {
      const Vec2 edge = (s.vertices[(i + 1) % n] - s.vertices[i]).normalized();
      const double d = Vec2(edge.y(), -edge.x()).dot(s.vertices[i] - m.centroid);
      if (d < nearest_distance) {
        nearest = i;
        nearest_distance = d;
      }
    }
    const Vec2 from = s.vertices[nearest], to = s.vertices[(nearest + 1) % n];
    const double along = (m.centroid - from).dot(to - from) / (to - from).squaredNorm();
    if (along < 0.1 || along > 0.9) {
      body.shape = ShapeDescription{};
      body.shape.half_extents = {0.4, 0.3};
      body.position = {0.0, 0.3};
      on = {0.8, 0.3};
      return body;
    }
    on = {(to - from).norm(), nearest_distance};
    // Turn the edge to point along +x (counter-clockwise, so the body lies above it), then lift
    // the vertices' origin so that the edge lies on y = 0.
    const Vec2 e = to - from;
    body.angle = -std::atan2(e.y(), e.x());
    const Vec2 turned(std::cos(body.angle) * from.x() - std::sin(body.angle) * from.y(),
                      std::sin(body.angle) * from.x() + std::cos(body.angle) * from.y());
    body.position = {0.0, -turned.y()};
  }
  return body;
}

// Up to two joints between the dynamic bodies (indices 1 …) or a body and the ground.
void add_joints(Bytes& b, Scene& scene, int first_dynamic) {
  const int dynamic = static_cast<int>(scene.bodies.size()) - first_dynamic;
  const int count = b.integer(0, 2);
  for (int j = 0; j < count; ++j) {
    const int a = first_dynamic + b.integer(0, dynamic - 1);
    const BodyDescription& body_a = scene.bodies[a];
    JointDescription joint;
    const int partner = b.one_in(2) ? 0 : first_dynamic + b.integer(0, dynamic - 1);
    if (partner == a) continue;
    const BodyDescription& body_b = scene.bodies[partner];
    joint.bodies = {body_b.name, body_a.name};
    switch (b.integer(0, 3)) {
      case 0:
        joint.type = JointType::revolute;
        joint.anchor = body_a.position + Vec2(b.number(-0.3, 0.3), b.number(-0.3, 0.3));
        break;
      case 1:
        joint.type = JointType::distance;
        joint.anchors = {body_b.position + Vec2(0.0, b.number(0.5, 2.0)), body_a.position};
        break;
      case 2:
        if (partner == 0) continue;  // an angle limit relative to the ground: needs two bodies
        joint.type = JointType::angle_limit;
        joint.lower = b.number(-3.0, 0.0);
        joint.upper = *joint.lower + b.number(0.1, 3.0);
        break;
      default: {
        joint.type = JointType::incline;
        joint.body = body_a.name;
        joint.point = body_a.position;
        const double angle = b.number(0.0, 2.0 * M_PI);
        joint.normal = {std::cos(angle), std::sin(angle)};
        joint.one_sided = b.one_in(2);
        break;
      }
    }
    scene.joints.push_back(joint);
  }
}

GeneratedScene general(Bytes& b) {
  GeneratedScene g;
  g.passive = b.one_in(2);
  Scene& scene = g.scene;
  choose_method(b, scene);
  scene.bodies.push_back(ground());
  if (b.one_in(3)) {
    BodyDescription obstacle;
    obstacle.name = "obstacle";
    obstacle.shape = b.one_in(2) ? polygon(b) : any_shape(b);
    obstacle.position = {b.number(-3.0, 3.0), b.number(0.2, 1.5)};
    obstacle.angle = b.number(-M_PI, M_PI);
    obstacle.is_static = true;
    scene.bodies.push_back(obstacle);
  }
  const int first_dynamic = static_cast<int>(scene.bodies.size());
  const int count = b.integer(1, 8);
  for (int i = 0; i < count; ++i) {
    BodyDescription body;
    body.name = "b" + std::to_string(i);
    body.shape = any_shape(b);
    body.position = {b.number(-3.0, 3.0), b.number(0.3, 5.0)};
    body.angle = b.number(-M_PI, M_PI);
    body.density = b.number(0.3, 3.0);
    body.friction = b.number(0.0, 1.0);
    if (!g.passive) {
      body.restitution = b.one_in(2) ? 0.0 : b.number(0.0, 1.0);
      body.velocity = {b.number(-4.0, 4.0), b.number(-4.0, 4.0)};
      body.angular_velocity = b.number(-5.0, 5.0);
    }
    scene.bodies.push_back(body);
  }
  if (!g.passive) add_joints(b, scene, first_dynamic);
  g.steps = 240;
  return g;
}

GeneratedScene resting(Bytes& b) {
  GeneratedScene g;
  g.kind = SceneKind::resting;
  g.passive = true;
  choose_method(b, g.scene);
  g.scene.bodies = {ground(), resting_body(b, &g.face)};
  g.resting = "resting";
  g.steps = 300;
  return g;
}

// One body resting on the ground, sometimes a second one dropped a little onto it; stepped by
// `pgs` (its velocity MLCP is the one compared with the exact solution).
GeneratedScene island(Bytes& b) {
  GeneratedScene g;
  g.kind = SceneKind::island;
  g.passive = true;
  g.scene.solver = "pgs";
  g.scene.step.iterations = b.integer(4, 30);
  BodyDescription lower = resting_body(b);
  g.scene.bodies = {ground(), lower};
  if (b.one_in(2)) {
    BodyDescription upper;
    upper.name = "upper";
    upper.shape.half_extents = {b.number(0.1, 0.5), b.number(0.1, 0.5)};
    upper.position = {b.number(-0.3, 0.3), 2.0 + b.number(0.0, 1.0)};
    upper.angle = b.number(-0.3, 0.3);
    g.scene.bodies.push_back(upper);
  }
  g.steps = b.integer(1, 120);
  return g;
}

// A number of either sign whose size spans [low, high] evenly in its logarithm, or 0.
double signed_log(Bytes& b, double low, double high) {
  if (b.one_in(8)) return 0.0;
  const double size = b.log_number(low, high);
  return b.one_in(2) ? size : -size;
}

// Any shape, sized anywhere in the reader's ranges (scene_limits.h), evenly in the logarithm.
ShapeDescription wide_shape(Bytes& b) {
  namespace limits = scene_limits;
  ShapeDescription shape = any_shape(b);
  const double scale = b.log_number(limits::size.low, limits::size.high);
  switch (shape.type) {
    case ShapeType::box:
      shape.half_extents = {scale, b.log_number(limits::size.low, limits::size.high)};
      break;
    case ShapeType::circle:
      shape.radius = scale;
      break;
    case ShapeType::capsule:
      shape.radius = scale;
      shape.length = b.log_number(limits::capsule_length.low, limits::capsule_length.high);
      break;
    case ShapeType::polygon: {
      // the ellipse polygon made `scale` times bigger (it is at least 0.15 m across), kept
      // within the coordinates' range
      const double times = std::min(scale / 0.15, limits::coordinate.high / 2.0);
      for (Vec2& v : shape.vertices) v *= std::max(times, 1.0);
      break;
    }
  }
  return shape;
}

// Every value anywhere in the reader's ranges, evenly in its logarithm where the range spans
// decades: Δt from 1e-5 to 1 s, g to ±1e4 m/s² either way, sizes 0.02 m to 1e6 m, densities
// 1e-3 to 1e5, speeds to 1e4. Only the invariants that hold whatever the numbers are checked
// (finite, planar, λ's bounds): at the ends the results need not make sense (scene-format.md,
// "Ranges, and why"). Sweeps stop at 1000, as the loader fuzzer steps them, to keep an input
// within its time.
GeneratedScene wide(Bytes& b) {
  namespace limits = scene_limits;
  GeneratedScene g;
  g.kind = SceneKind::wide;
  Scene& scene = g.scene;
  choose_method(b, scene);
  scene.step.dt = b.log_number(limits::dt.low, limits::dt.high);
  scene.step.iterations = b.integer(0, 1000);
  scene.step.beta = b.number(limits::beta.low, limits::beta.high);
  scene.step.gravity.head<2>() = Vec2(signed_log(b, 1e-3, limits::gravity.high),
                                      signed_log(b, 1e-3, limits::gravity.high));
  scene.bodies.push_back(ground());
  const int count = b.integer(1, 6);
  for (int i = 0; i < count; ++i) {
    BodyDescription body;
    body.name = "w" + std::to_string(i);
    body.shape = wide_shape(b);
    body.position = {signed_log(b, 1e-3, limits::coordinate.high),
                     signed_log(b, 1e-3, limits::coordinate.high)};
    body.angle = signed_log(b, 1e-6, limits::angle.high);
    body.is_static = b.one_in(6);
    body.density = b.log_number(limits::density.low, limits::density.high);
    body.friction = b.number(limits::friction.low, limits::friction.high);
    body.restitution = b.number(limits::restitution.low, limits::restitution.high);
    body.velocity = {signed_log(b, 1e-3, limits::speed.high), signed_log(b, 1e-3, limits::speed.high)};
    body.angular_velocity = signed_log(b, 1e-3, limits::angular_speed.high);
    scene.bodies.push_back(body);
  }
  g.steps = 120;
  return g;
}

}  // namespace

GeneratedScene generate_scene(Bytes& bytes) {
  switch (bytes.byte() % 4) {
    case 1: return resting(bytes);
    case 2: return island(bytes);
    case 3: return wide(bytes);
    default: return general(bytes);
  }
}

GeneratedScene regression_scene(const std::string& json_text, const std::string& origin) {
  const nlohmann::json j = nlohmann::json::parse(json_text);
  GeneratedScene g;
  const std::string kind = j.at("kind").get<std::string>();
  if (kind == "general") g.kind = SceneKind::general;
  else if (kind == "resting") g.kind = SceneKind::resting;
  else if (kind == "island") g.kind = SceneKind::island;
  else if (kind == "wide") g.kind = SceneKind::wide;
  else throw std::invalid_argument(origin + ": kind: no such kind, got \"" + kind + "\"");
  g.passive = j.at("passive").get<bool>();
  g.steps = j.at("steps").get<int>();
  if (j.contains("resting")) {
    g.resting = j.at("resting").get<std::string>();
    g.face = {j.at("face").at(0).get<double>(), j.at("face").at(1).get<double>()};
  }
  g.scene = parse_scene(j.at("scene").dump(), origin);
  return g;
}

}  // namespace lamina::fuzz
