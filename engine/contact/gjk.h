// GJK and EPA in the plane: the distance between two convex shapes and, when they overlap, the
// depth and direction of their penetration. The text leaves collision detection to van den
// Bergen [9] and Ericson [10] ("GJK and EPA are both important: know them well"); Lamina's
// versions are written to be read beside docs/collision.md.
//
// Every shape is a core inflated by a radius (Box2D v3's form): a polygon or box is its vertices
// with radius 0, a circle is one point with radius ρ, a capsule is a segment with radius ρ.
// The algorithms work on the cores; the radii are added back by the narrow phase.
//
//   A, B            the two cores (body 1's and body 2's), world frame
//   D = B − A       their Minkowski difference {b − a}; the cores overlap iff 0 ∈ D
//   s_D(d)          the support point of D along d: s_B(d) − s_A(−d), each s the vertex of
//                   largest d · v
//   distance        min over D of |w|, the distance between the cores (0 when they overlap)
//   n               unit, from A to B: the direction of D's point nearest the origin (GJK), or
//                   minus the outward normal m of D's edge nearest the origin (EPA: that edge's
//                   point nearest the origin is depth·m = b − a, so B moved by depth·n touches A)
//   depth           EPA: how far B must move along n for the cores to only touch
//
// GJK keeps a simplex (1 to 3 points of D) and moves it toward the origin: each iteration finds
// the simplex's point nearest the origin, drops the simplex points it does not need, and adds
// s_D(−w) along the search direction −w. It stops when the new support point is no nearer
// (w · w − w · s ≤ ε |w|², ε relative) or is one it already had, or when the simplex is a
// triangle holding the origin.
// EPA starts from GJK's final triangle (built out to one if GJK stopped with fewer points) and
// grows the polygon toward D's boundary: it takes the edge nearest the origin, asks D for its
// support point along that edge's outward normal, and stops when the support point is no
// farther out than the edge (to a relative ε).
#pragma once

#include <array>
#include <vector>

#include "contact/planar.h"

namespace lamina {

// A convex core in the world frame, inflated by `radius`.
struct Convex {
  static constexpr int max_vertices = 8;
  std::array<Vec2, max_vertices> vertices{};  // counter-clockwise when count ≥ 3, in m
  int count = 0;                              // 1: a point, 2: a segment, 3..8: a polygon
  double radius = 0.0;                        // ρ added around the core, in m

  // The index of the vertex of largest d · v (the first one on a tie, so results are
  // deterministic).
  int support(const Vec2& d) const;
};

// One point of the Minkowski difference, with the vertex of each core it came from.
struct SimplexVertex {
  Vec2 a = Vec2::Zero();  // a vertex of A, in m
  Vec2 b = Vec2::Zero();  // a vertex of B, in m
  Vec2 w = Vec2::Zero();  // b − a, in m
  int index_a = 0;        // which vertex of A
  int index_b = 0;        // which vertex of B
};

struct Simplex {
  std::array<SimplexVertex, 3> points{};  // the first `count` are in use
  int count = 0;                          // 1, 2 or 3
};

// One GJK iteration, as the tutorial draws it.
struct GjkIteration {
  Simplex simplex;              // after the iteration's reduction, before the new point is added
  Vec2 closest = Vec2::Zero();  // the simplex's point nearest the origin, in m
  Vec2 direction = Vec2::Zero();  // the search direction −closest (unit, or zero at the origin)
  SimplexVertex support;        // s_D(direction), the point the iteration adds
};

struct GjkResult {
  bool overlap = false;          // the cores overlap (or touch at a point of D at the origin)
  double distance = 0.0;         // between the cores, in m (0 when they overlap)
  Vec2 point_a = Vec2::Zero();   // A's point nearest B, world, in m (meaningful when !overlap)
  Vec2 point_b = Vec2::Zero();   // B's point nearest A, world, in m
  Vec2 normal = Vec2::UnitY();   // (point_b − point_a)/distance, unit (when !overlap)
  int iterations = 0;            // support points asked for
  Simplex simplex;               // the final simplex (EPA starts from it)
};

// The distance between two cores and their closest points; `record`, when given, receives
// each iteration. Terminates within gjk_max_iterations whatever the input.
GjkResult gjk(const Convex& a, const Convex& b, std::vector<GjkIteration>* record = nullptr);

// One EPA iteration, as the tutorial draws it.
struct EpaIteration {
  std::vector<Vec2> polytope;   // D's points found so far, counter-clockwise, in m
  int nearest_edge = 0;         // the edge (polytope[k], polytope[k+1]) nearest the origin
  Vec2 normal = Vec2::UnitY();  // its outward unit normal
  double distance = 0.0;        // its distance from the origin, in m
  Vec2 support = Vec2::Zero();  // s_D(normal), in m
};

struct EpaResult {
  Vec2 normal = Vec2::UnitY();  // n, unit, from A to B: moving B by depth·n separates them
  double depth = 0.0;           // of the cores, in m (≥ 0)
  Vec2 point_a = Vec2::Zero();  // A's point deepest inside B, world, in m
  Vec2 point_b = Vec2::Zero();  // B's point deepest inside A: point_a − depth·n, in m
  int iterations = 0;           // support points asked for by the expansion (not counting
                                // those that grow a touching simplex to the first triangle)
};

// The penetration of two overlapping cores, starting from GJK's result for them; `record`, when
// given, receives each iteration. Terminates within epa_max_iterations whatever the input.
EpaResult epa(const Convex& a, const Convex& b, const GjkResult& overlap,
              std::vector<EpaIteration>* record = nullptr);

// The most support points either asks for before giving its best answer so far.
inline constexpr int gjk_max_iterations = 32;
inline constexpr int epa_max_iterations = 32;

}  // namespace lamina
