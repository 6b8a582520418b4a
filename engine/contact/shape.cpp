#include "contact/shape.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kinematics/require.h"

namespace lamina {

Shape Shape::box(double half_x, double half_y) {
  Shape shape;
  shape.kind = Kind::box;
  shape.half_extents = Vec2(half_x, half_y);
  return shape;
}

Shape Shape::circle(double radius) {
  Shape shape;
  shape.kind = Kind::circle;
  shape.radius = radius;
  return shape;
}

Shape Shape::polygon(const std::vector<Vec2>& vertices) {
  const std::optional<std::string> problem = polygon_problem(vertices);
  require(!problem, "shape: " + problem.value_or(""));
  Shape shape;
  shape.kind = Kind::polygon;
  shape.vertex_count = static_cast<int>(vertices.size());
  std::copy(vertices.begin(), vertices.end(), shape.vertices.begin());
  return shape;
}

Shape Shape::capsule(double radius, double length) {
  Shape shape;
  shape.kind = Kind::capsule;
  shape.radius = radius;
  shape.length = length;
  return shape;
}

Convex core_of(const Shape& shape, const Pose2& pose) {
  Convex core;
  switch (shape.kind) {
    case Shape::Kind::box: {
      const Vec2& h = shape.half_extents;
      core.count = 4;
      core.vertices[0] = pose.to_world(Vec2(-h.x(), -h.y()));
      core.vertices[1] = pose.to_world(Vec2(h.x(), -h.y()));
      core.vertices[2] = pose.to_world(Vec2(h.x(), h.y()));
      core.vertices[3] = pose.to_world(Vec2(-h.x(), h.y()));
      break;
    }
    case Shape::Kind::circle:
      core.count = 1;
      core.vertices[0] = pose.x;
      core.radius = shape.radius;
      break;
    case Shape::Kind::polygon:
      core.count = shape.vertex_count;
      for (int i = 0; i < core.count; ++i) core.vertices[i] = pose.to_world(shape.vertices[i]);
      break;
    case Shape::Kind::capsule:
      core.count = 2;
      core.vertices[0] = pose.to_world(Vec2(-0.5 * shape.length, 0.0));
      core.vertices[1] = pose.to_world(Vec2(0.5 * shape.length, 0.0));
      core.radius = shape.radius;
      break;
  }
  return core;
}

std::optional<std::string> polygon_problem(const std::vector<Vec2>& vertices) {
  const int n = static_cast<int>(vertices.size());
  if (n < 3 || n > Convex::max_vertices) {
    return "a polygon has 3 to 8 vertices, got " + std::to_string(n);
  }
  double twice_area = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec2& a = vertices[i];
    const Vec2& b = vertices[(i + 1) % n];
    twice_area += a.x() * b.y() - a.y() * b.x();
    if (!a.allFinite()) return "vertex " + std::to_string(i) + " is not a finite point";
    if (a == b) {
      return "vertex " + std::to_string((i + 1) % n) + " repeats vertex " + std::to_string(i);
    }
  }
  const double sense = twice_area < 0.0 ? -1.0 : 1.0;  // the order most of the turns take
  for (int i = 0; i < n; ++i) {
    const Vec2 in = vertices[i] - vertices[(i + n - 1) % n];
    const Vec2 out = vertices[(i + 1) % n] - vertices[i];
    const double turn = in.x() * out.y() - in.y() * out.x();  // |in||out| sin of the turn
    if (std::abs(turn) <= 1e-6 * in.norm() * out.norm()) {
      return "vertices " + std::to_string((i + n - 1) % n) + ", " + std::to_string(i) + " and " +
             std::to_string((i + 1) % n) + " lie on one line";
    }
    if (turn * sense < 0.0) {
      return "not convex: the turn at vertex " + std::to_string(i) + " goes the other way";
    }
  }
  if (twice_area < 0.0) return "the vertices run clockwise; give them counter-clockwise";
  return std::nullopt;
}

double combined_friction(const Material& a, const Material& b) {
  return std::sqrt(a.friction * b.friction);
}

double combined_restitution(const Material& a, const Material& b) {
  return std::max(a.restitution, b.restitution);
}

Aabb bounding_box(const Shape& shape, const Pose2& pose) {
  // A rotated box reaches |R| h along each axis; a circle reaches ρ.
  if (shape.is_box() || shape.is_circle()) {
    const Vec2 reach = shape.is_box() ? Vec2(pose.R.cwiseAbs() * shape.half_extents)
                                      : Vec2(shape.radius, shape.radius);
    return Aabb{pose.x - reach, pose.x + reach};
  }
  // A polygon or capsule: its core's extreme vertices, widened by its radius.
  const Convex core = core_of(shape, pose);
  Aabb box{core.vertices[0], core.vertices[0]};
  for (int i = 1; i < core.count; ++i) {
    box.min = box.min.cwiseMin(core.vertices[i]);
    box.max = box.max.cwiseMax(core.vertices[i]);
  }
  const Vec2 widen(core.radius, core.radius);
  return Aabb{box.min - widen, box.max + widen};
}

double outer_radius(const Shape& shape) {
  switch (shape.kind) {
    case Shape::Kind::box:
      return shape.half_extents.norm();
    case Shape::Kind::circle:
      return shape.radius;
    case Shape::Kind::capsule:
      return 0.5 * shape.length + shape.radius;
    case Shape::Kind::polygon:
      break;
  }
  double farthest = 0.0;
  for (int i = 0; i < shape.vertex_count; ++i) farthest = std::max(farthest, shape.vertices[i].norm());
  return farthest;
}

bool contains(const Shape& shape, const Pose2& pose, const Vec2& point, double tolerance) {
  const Vec2 r = pose.to_body(point);
  switch (shape.kind) {
    case Shape::Kind::box:
      return (r.cwiseAbs() - shape.half_extents).maxCoeff() <= tolerance;
    case Shape::Kind::circle:
      return r.norm() <= shape.radius + tolerance;
    case Shape::Kind::polygon:
      // On the inner side of every edge: (v_i+1 − v_i) × (r − v_i) ≥ −tolerance |v_i+1 − v_i|.
      for (int i = 0; i < shape.vertex_count; ++i) {
        const Vec2& a = shape.vertices[i];
        const Vec2 edge = shape.vertices[(i + 1) % shape.vertex_count] - a;
        const Vec2 to = r - a;
        if (edge.x() * to.y() - edge.y() * to.x() < -tolerance * edge.norm()) return false;
      }
      return true;
    case Shape::Kind::capsule: {
      const double along = std::max(std::abs(r.x()) - 0.5 * shape.length, 0.0);
      return Vec2(along, r.y()).norm() <= shape.radius + tolerance;
    }
  }
  return false;
}

void validate(const Shape& shape) {
  switch (shape.kind) {
    case Shape::Kind::box:
      require_positive(shape.half_extents.x(), "shape: box half extent x");
      require_positive(shape.half_extents.y(), "shape: box half extent y");
      break;
    case Shape::Kind::circle:
      require_positive(shape.radius, "shape: circle radius");
      break;
    case Shape::Kind::polygon: {
      const std::vector<Vec2> vertices(shape.vertices.begin(),
                                       shape.vertices.begin() + shape.vertex_count);
      const std::optional<std::string> problem = polygon_problem(vertices);
      require(!problem, "shape: " + problem.value_or(""));
      break;
    }
    case Shape::Kind::capsule:
      require_positive(shape.radius, "shape: capsule radius");
      require(std::isfinite(shape.length) && shape.length >= 0.0,
              "shape: capsule length must be finite and ≥ 0, got " + std::to_string(shape.length));
      break;
  }
}

void validate(const Material& material) {
  require(std::isfinite(material.friction) && material.friction >= 0.0,
          "material: friction must be finite and ≥ 0, got " + std::to_string(material.friction));
  require(std::isfinite(material.restitution) && material.restitution >= 0.0 &&
              material.restitution <= 1.0,
          "material: restitution must be in [0, 1], got " + std::to_string(material.restitution));
}

}  // namespace lamina
