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

double combined_friction(const Material& a, const Material& b) {
  return std::sqrt(a.friction * b.friction);
}

double combined_restitution(const Material& a, const Material& b) {
  return std::max(a.restitution, b.restitution);
}

Aabb bounding_box(const Shape& shape, const Pose2& pose) {
  // A rotated box reaches |R| h along each axis; a circle reaches ρ.
  const Vec2 reach = shape.is_box() ? Vec2(pose.R.cwiseAbs() * shape.half_extents)
                                    : Vec2(shape.radius, shape.radius);
  return Aabb{pose.x - reach, pose.x + reach};
}

bool contains(const Shape& shape, const Pose2& pose, const Vec2& point, double tolerance) {
  const Vec2 r = pose.to_body(point);
  if (!shape.is_box()) return r.norm() <= shape.radius + tolerance;
  return (r.cwiseAbs() - shape.half_extents).maxCoeff() <= tolerance;
}

void validate(const Shape& shape) {
  if (shape.is_box()) {
    require_positive(shape.half_extents.x(), "shape: box half extent x");
    require_positive(shape.half_extents.y(), "shape: box half extent y");
  } else {
    require_positive(shape.radius, "shape: circle radius");
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
