// Narrow phase: the deepest point of a pair, as the text's collision detection returns it
// (chapter 4, Fig 4-2: "only the single deepest point"). The text leaves the algorithm to its
// references [9] and [10]; Lamina's is planar and written for clarity.
//
//   point      the incident body's point deepest inside the reference body
//   normal n   unit, from body 1 to body 2 (the n1 of eq. 4-1)
//   depth      how far `point` is inside, along n, in m; 0 when exactly touching (still a contact)
//   reference  the body whose surface n is normal to; the other body is the incident one
//
// Box–box: the separating axis test over both boxes' face normals. For a face with outward
// normal n_f at distance h_f from the reference centre x_r, the separation of the other box is
//   s_f = min over its vertices v of  n_f · (v − x_r) − h_f
// The boxes overlap (or touch) when the largest s_f over all eight faces is ≤ 0; that face is
// the reference face and the depth of a vertex inside the reference box is −(n_f · (v − x_r) − h_f).
// Box–circle and circle–circle are closed forms. Every other pair (a polygon or a capsule in it)
// goes through GJK and EPA (gjk.h, convex_contact.cpp); box–box keeps its separating axes as the
// fast path, checked against GJK/EPA in tests/test_collision.cpp.
#pragma once

#include <array>
#include <optional>

#include "contact/shape.h"

namespace lamina {

struct Collision {
  Vec2 point = Vec2::Zero();   // the deepest point, world frame, in m
  Vec2 normal = Vec2::UnitY(); // n, unit, from body 1 to body 2
  double depth = 0.0;          // penetration of `point` along n, in m (≥ 0)
  int reference = 0;           // 0: n is normal to body 1's surface; 1: to body 2's
};

// How the narrow phase picks among equally deep vertices. The text returns "the deepest point"
// as if there were always one; a box landing flat has two, and taking the first one found makes
// it spin. Lamina's rule (beyond the text): among the vertices within `tolerance` of the deepest,
// the one farthest from the pair's cached points, or on a first contact their midpoint.
struct TieRule {
  bool break_ties = true;   // false: the first deepest vertex found, as the text reads
  double tolerance = 5e-4;  // vertices this close to the deepest count as equally deep, in m
  // A first contact's tied vertices of one edge give their midpoint (a flat landing pushes
  // straight up); false: the first of them, a corner, whose partner the cache gains next step
  // (chapter 6's soft-step, closer to Box2D v3's clipped two-point manifold).
  bool midpoint_first = true;
};

// A candidate point inside the reference shape by up to this much less than nothing still counts
// as inside: the rounding of Rᵀ(p − x) for shapes placed exactly touching, far below any
// physical margin. Every narrow phase's test of containment uses it.
constexpr double containment_tolerance = 1e-9;  // in m

// The points a pair's cache already holds (world frame), for breaking ties between equally deep
// vertices: the narrow phase returns the one farthest from them.
struct CachedPoints {
  std::array<Vec2, 2> points{Vec2::Zero(), Vec2::Zero()};  // world points, in m
  int count = 0;                                            // how many are valid
};

// The deepest point of two shapes at their poses, or nothing when they are apart; equally deep
// vertices are told apart by `ties`.
std::optional<Collision> collide(const Shape& shape1, const Pose2& pose1, const Shape& shape2,
                                 const Pose2& pose2, const CachedPoints& cached,
                                 const TieRule& ties);

// The deepest of `count` candidate points, equally deep ones told apart by `ties` (the rule
// above; box_box.cpp and convex_contact.cpp gather the candidates).
Collision choose_deepest(const Collision* candidates, int count, const CachedPoints& cached,
                         const TieRule& ties);

// The pair types; `collide` dispatches to them (box–circle also serves circle–box).
std::optional<Collision> collide_boxes(const Shape& box1, const Pose2& pose1, const Shape& box2,
                                       const Pose2& pose2, const CachedPoints& cached,
                                       const TieRule& ties);
std::optional<Collision> collide_box_circle(const Shape& box, const Pose2& box_pose,
                                            const Shape& circle, const Pose2& circle_pose);
std::optional<Collision> collide_circles(const Shape& circle1, const Pose2& pose1,
                                         const Shape& circle2, const Pose2& pose2);
// Any two shapes, by GJK and EPA on their cores (convex_contact.cpp).
std::optional<Collision> collide_convex(const Shape& shape1, const Pose2& pose1,
                                        const Shape& shape2, const Pose2& pose2,
                                        const CachedPoints& cached, const TieRule& ties);

}  // namespace lamina
