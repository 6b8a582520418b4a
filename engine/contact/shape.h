// The shapes of chapter 4's collision detection, the material of a body, and their bounding boxes.
//
//   box      half extents (hx, hy): the points |r_x| ≤ hx, |r_y| ≤ hy of the body frame
//   circle   radius ρ: the points |r| ≤ ρ of the body frame
//   polygon  3 to 8 vertices v_i, counter-clockwise, convex: the points on the inner side of
//            every edge (v_i, v_i+1); the vertices are about the centroid (mass_properties.h)
//   capsule  radius ρ and length l: the points within ρ of the segment from (−l/2, 0) to
//            (l/2, 0) of the body frame
//   μ       friction coefficient of a pair: √(μ1 μ2)        (Box2D's rule, beyond the text)
//   e       restitution of a pair: max(e1, e2)               (Box2D's rule, beyond the text)
// Shapes are centred on the body's centre of mass; a static body may be any shape (the ground
// is a static box). For GJK and EPA (gjk.h) every shape is a core inflated by a radius: a box or
// polygon its vertices with radius 0, a circle its centre with ρ, a capsule its segment with ρ.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contact/gjk.h"
#include "contact/planar.h"

namespace lamina {

struct Shape {
  enum class Kind { box, circle, polygon, capsule };
  Kind kind = Kind::box;                    // which of the four shapes
  Vec2 half_extents = Vec2(0.5, 0.5);      // (hx, hy) of a box, in m
  double radius = 0.0;                      // ρ of a circle or a capsule, in m
  double length = 0.0;                      // l of a capsule, between its caps' centres, in m
  std::array<Vec2, Convex::max_vertices> vertices{};  // a polygon's v_i, body frame, in m
  int vertex_count = 0;                     // how many of `vertices` a polygon has

  // Sizes are checked where a shape enters a World (validate below).
  static Shape box(double half_x, double half_y);
  static Shape circle(double radius);
  // `vertices` about the centre of mass, counter-clockwise; throws std::invalid_argument with
  // polygon_problem's line when they are not a convex polygon.
  static Shape polygon(const std::vector<Vec2>& vertices);
  static Shape capsule(double radius, double length);

  bool is_box() const { return kind == Kind::box; }
  bool is_circle() const { return kind == Kind::circle; }
};

// The shape's core at a pose, world frame, with its radius (gjk.h).
Convex core_of(const Shape& shape, const Pose2& pose);

// What is wrong with a polygon's vertices, or nothing: fewer than 3 or more than 8, a vertex
// repeating its neighbour, three neighbours on one line (the turn at a vertex below 1e-6 of its
// edges' lengths, relative), clockwise order, or a turn the other way (not convex).
std::optional<std::string> polygon_problem(const std::vector<Vec2>& vertices);

// How two bodies rub and bounce. One default friction for scene files and code alike: 0.6, what
// every Lamina scene uses (wood on wood, rubber on concrete are 0.4 to 0.8). Box2D's fixtures
// default to 0.2, so a comparison with Box2D gives both engines μ explicitly.
struct Material {
  double friction = 0.6;     // μ, dimensionless, ≥ 0 (scene files' default too; see below)
  double restitution = 0.0;  // e, the fraction of approach speed returned, in [0, 1]
};

// μ of a pair: √(μ1 μ2) (Box2D's b2MixFriction; the text gives one μ per pair).
double combined_friction(const Material& a, const Material& b);
// e of a pair: max(e1, e2) (Box2D's b2MixRestitution; restitution is beyond the text).
double combined_restitution(const Material& a, const Material& b);

// An axis-aligned bounding box in the plane.
struct Aabb {
  Vec2 min = Vec2::Zero();  // lower-left corner, in m
  Vec2 max = Vec2::Zero();  // upper-right corner, in m

  // Boxes that touch overlap: exactly touching bodies are in contact (separation 0).
  bool overlaps(const Aabb& other) const {
    return min.x() <= other.max.x() && other.min.x() <= max.x() && min.y() <= other.max.y() &&
           other.min.y() <= max.y();
  }
};

// The bounding box of a shape at a pose.
Aabb bounding_box(const Shape& shape, const Pose2& pose);

// The farthest any point of the shape lies from its centre of mass, in m: how far it can reach
// at any angle.
double outer_radius(const Shape& shape);

// Whether a world point lies inside the shape at a pose, or outside by at most `tolerance` (m).
bool contains(const Shape& shape, const Pose2& pose, const Vec2& point, double tolerance);

// Throws std::invalid_argument unless the shape's sizes are finite and positive (a capsule's
// length may be 0) and a polygon's vertices pass polygon_problem.
void validate(const Shape& shape);
// Throws std::invalid_argument unless μ ≥ 0 and 0 ≤ e ≤ 1, both finite.
void validate(const Material& material);

}  // namespace lamina
