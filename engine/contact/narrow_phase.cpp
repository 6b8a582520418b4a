#include "contact/narrow_phase.h"

#include <cmath>
#include <limits>

namespace lamina {

// The deepest candidate; with ties broken, among candidates within the tolerance of the deepest:
// on a first contact the midpoint of the deepest one's reference group (two vertices of one
// edge: a flat landing pushes straight up), unless ties.midpoint_first is off; otherwise the
// candidate farthest from the cached points, so that the cache gains the point it lacks (with
// none cached, the first tied one). Ties beyond that go to the first candidate, keeping the
// result deterministic.
Collision choose_deepest(const Collision* candidates, int count, const CachedPoints& cached,
                         const TieRule& ties) {
  double deepest = -std::numeric_limits<double>::infinity();
  int first = 0;
  for (int k = 0; k < count; ++k) {
    if (candidates[k].depth > deepest) {
      deepest = candidates[k].depth;
      first = k;
    }
  }
  if (!ties.break_ties) return candidates[first];
  const auto tied = [&](const Collision& c) { return c.depth >= deepest - ties.tolerance; };
  if (cached.count == 0 && ties.midpoint_first) {
    Collision mid = candidates[first];
    mid.point.setZero();
    mid.depth = 0.0;
    int n = 0;
    for (int k = 0; k < count; ++k) {
      const Collision& c = candidates[k];
      if (!tied(c) || c.reference != candidates[first].reference) continue;
      mid.point += c.point;
      mid.depth += c.depth;
      ++n;
    }
    mid.point /= n;
    mid.depth /= n;
    return mid;
  }
  int chosen = first;
  double farthest = -1.0;
  for (int k = 0; k < count; ++k) {
    if (!tied(candidates[k])) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < cached.count; ++j) {
      nearest = std::min(nearest, (candidates[k].point - cached.points[j]).norm());
    }
    if (nearest > farthest) {
      farthest = nearest;
      chosen = k;
    }
  }
  return candidates[chosen];
}

std::optional<Collision> collide_box_circle(const Shape& box, const Pose2& box_pose,
                                            const Shape& circle, const Pose2& circle_pose) {
  const Vec2& h = box.half_extents;
  const Vec2 centre = box_pose.to_body(circle_pose.x);  // circle centre in the box frame
  const Vec2 closest = centre.cwiseMax(-h).cwiseMin(h);  // nearest point of the box to it
  Vec2 local_normal;                                     // n in the box frame, box → circle
  double centre_distance;  // signed distance of the centre from the box surface along n, in m
  if (closest == centre) {
    // The centre is inside (or on) the box: leave through the nearest face.
    const Vec2 inside = h - centre.cwiseAbs();  // distance to the x and y faces
    const int axis = inside.x() <= inside.y() ? 0 : 1;
    local_normal = Vec2::Zero();
    local_normal[axis] = centre[axis] < 0.0 ? -1.0 : 1.0;
    centre_distance = -inside[axis];
  } else {
    const Vec2 offset = centre - closest;
    centre_distance = offset.norm();
    if (centre_distance > circle.radius) return std::nullopt;
    local_normal = offset / centre_distance;
  }
  Collision c;
  c.normal = box_pose.R * local_normal;
  c.depth = circle.radius - centre_distance;
  // The circle's deepest point is the one facing the box.
  c.point = circle_pose.x - circle.radius * c.normal;
  c.reference = 0;
  return c;
}

std::optional<Collision> collide_circles(const Shape& circle1, const Pose2& pose1,
                                         const Shape& circle2, const Pose2& pose2) {
  const Vec2 offset = pose2.x - pose1.x;
  const double distance = offset.norm();
  const double reach = circle1.radius + circle2.radius;
  if (distance > reach) return std::nullopt;
  Collision c;
  // Concentric circles have no preferred direction: push along +y, "up".
  c.normal = distance > 0.0 ? Vec2(offset / distance) : Vec2::UnitY();
  c.depth = reach - distance;
  c.point = pose2.x - circle2.radius * c.normal;  // circle 2's point deepest inside circle 1
  c.reference = 0;
  return c;
}

std::optional<Collision> collide(const Shape& shape1, const Pose2& pose1, const Shape& shape2,
                                 const Pose2& pose2, const CachedPoints& cached,
                                 const TieRule& ties) {
  if (shape1.is_box() && shape2.is_box()) {
    return collide_boxes(shape1, pose1, shape2, pose2, cached, ties);
  }
  const bool box_and_circle = (shape1.is_box() && shape2.is_circle()) ||
                              (shape1.is_circle() && shape2.is_box());
  if (!box_and_circle && !(shape1.is_circle() && shape2.is_circle())) {
    return collide_convex(shape1, pose1, shape2, pose2, cached, ties);
  }
  if (shape1.is_box()) return collide_box_circle(shape1, pose1, shape2, pose2);
  if (shape2.is_box()) {
    // circle–box is box–circle seen from the other side: n turns round, the box is body 2.
    std::optional<Collision> c = collide_box_circle(shape2, pose2, shape1, pose1);
    if (c) {
      c->normal = -c->normal;
      c->reference = 1;
    }
    return c;
  }
  return collide_circles(shape1, pose1, shape2, pose2);
}

}  // namespace lamina
