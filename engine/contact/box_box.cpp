// Box–box: the separating axis test, and the deepest vertex with the ties the literal
// "deepest point" gets wrong (docs/ch4-contact-model.md, "Beyond the text").
#include <limits>

#include "contact/narrow_phase.h"

namespace lamina {
namespace {

// A vertex inside a box by up to this much less than nothing still counts as inside: the
// rounding of Rᵀ(p − x) for boxes placed exactly touching, far below any physical margin.
constexpr double containment_tolerance = 1e-9;  // in m

// A face of a box: its outward normal and its distance from the centre.
struct Face {
  Vec2 normal;    // n_f, unit, world frame
  double offset;  // h_f, in m
};

std::array<Face, 4> faces_of(const Shape& box, const Pose2& pose) {
  const Vec2& h = box.half_extents;
  const Vec2 ex = pose.R.col(0);
  const Vec2 ey = pose.R.col(1);
  return {Face{ex, h.x()}, Face{ey, h.y()}, Face{-ex, h.x()}, Face{-ey, h.y()}};
}

std::array<Vec2, 4> vertices_of(const Shape& box, const Pose2& pose) {
  const Vec2& h = box.half_extents;
  return {pose.to_world(Vec2(-h.x(), -h.y())), pose.to_world(Vec2(h.x(), -h.y())),
          pose.to_world(Vec2(h.x(), h.y())), pose.to_world(Vec2(-h.x(), h.y()))};
}

// The reference box's face that separates it most from the other box's vertices.
struct BestFace {
  Face face;          // the face of largest separation
  double separation;  // its s_f, in m (> 0: apart)
};

BestFace best_face(const Shape& box, const Pose2& pose, const std::array<Vec2, 4>& others) {
  BestFace best{Face{Vec2::Zero(), 0.0}, -std::numeric_limits<double>::infinity()};
  for (const Face& face : faces_of(box, pose)) {
    double s = std::numeric_limits<double>::infinity();
    // s_f = min over the other box's vertices of n_f · (v − x_r) − h_f
    for (const Vec2& v : others) s = std::min(s, face.normal.dot(v - pose.x) - face.offset);
    if (s > best.separation) best = BestFace{face, s};
  }
  return best;
}

// The candidate points of a pair: at most the 4 vertices of each box; no allocation.
struct Candidates {
  std::array<Collision, 8> items;  // the candidates found
  int count = 0;                   // how many of items are valid

  void add(const Collision& c) { items[count++] = c; }
  const Collision* begin() const { return items.data(); }
  const Collision* end() const { return items.data() + count; }
};

// Among candidates within tie_tolerance of the deepest: on a first contact the midpoint of the
// deepest one's reference group (two vertices of one edge: a flat landing pushes straight up);
// otherwise the candidate farthest from the cached points, so that the cache gains the point
// it lacks. Ties beyond that go to the first candidate, keeping the result deterministic.
Collision choose(const Candidates& candidates, const CachedPoints& cached,
                 double tie_tolerance) {
  double deepest = -std::numeric_limits<double>::infinity();
  int first = 0;
  for (int k = 0; k < candidates.count; ++k) {
    if (candidates.items[k].depth > deepest) {
      deepest = candidates.items[k].depth;
      first = k;
    }
  }
  const auto tied = [&](const Collision& c) { return c.depth >= deepest - tie_tolerance; };
  if (cached.count == 0) {
    Collision mid = candidates.items[first];
    mid.point.setZero();
    mid.depth = 0.0;
    int n = 0;
    for (const Collision& c : candidates) {
      if (!tied(c) || c.reference != candidates.items[first].reference) continue;
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
  for (int k = 0; k < candidates.count; ++k) {
    if (!tied(candidates.items[k])) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < cached.count; ++j) {
      nearest = std::min(nearest, (candidates.items[k].point - cached.points[j]).norm());
    }
    if (nearest > farthest) {
      farthest = nearest;
      chosen = k;
    }
  }
  return candidates.items[chosen];
}

}  // namespace

std::optional<Collision> collide_boxes(const Shape& box1, const Pose2& pose1, const Shape& box2,
                                       const Pose2& pose2, const CachedPoints& cached,
                                       double tie_tolerance) {
  const std::array<Vec2, 4> corners1 = vertices_of(box1, pose1);
  const std::array<Vec2, 4> corners2 = vertices_of(box2, pose2);
  // Separating axis test over both boxes' face normals: body 1's faces against body 2's
  // vertices and the other way round.
  const std::array<BestFace, 2> best{best_face(box1, pose1, corners2),
                                     best_face(box2, pose2, corners1)};
  const double separation = std::max(best[0].separation, best[1].separation);
  if (separation > 0.0) return std::nullopt;  // a separating axis: apart (0 is touching)

  // Candidates: the incident vertices inside the reference box, trying both boxes as the
  // reference when their faces separate equally (a box resting half over another has one
  // supported vertex of its own and one of the box below).
  const std::array<const Shape*, 2> shapes{&box1, &box2};
  const std::array<const Pose2*, 2> poses{&pose1, &pose2};
  const std::array<const std::array<Vec2, 4>*, 2> corners{&corners1, &corners2};
  Candidates candidates;
  for (int ref = 0; ref < 2; ++ref) {
    if (best[ref].separation < separation - tie_tolerance) continue;
    const Face& face = best[ref].face;
    for (const Vec2& v : *corners[1 - ref]) {
      if (!contains(*shapes[ref], *poses[ref], v, containment_tolerance)) continue;
      Collision c;
      c.point = v;
      c.depth = face.offset - face.normal.dot(v - poses[ref]->x);
      // n points from body 1 to body 2: body 1's outward face normal, or body 2's reversed.
      c.normal = ref == 0 ? face.normal : Vec2(-face.normal);
      c.reference = ref;
      candidates.add(c);
    }
  }
  if (candidates.count == 0) {
    // Two boxes crossing like a plus sign overlap with no vertex inside the other: return the
    // incident vertex deepest past the separating-axis face.
    const int ref = best[0].separation >= best[1].separation ? 0 : 1;
    const Face& face = best[ref].face;
    Collision c;
    c.depth = -std::numeric_limits<double>::infinity();
    for (const Vec2& v : *corners[1 - ref]) {
      const double depth = face.offset - face.normal.dot(v - poses[ref]->x);
      if (depth > c.depth) {
        c.depth = depth;
        c.point = v;
      }
    }
    c.normal = ref == 0 ? face.normal : Vec2(-face.normal);
    c.reference = ref;
    return c;
  }
  return choose(candidates, cached, tie_tolerance);
}

}  // namespace lamina
