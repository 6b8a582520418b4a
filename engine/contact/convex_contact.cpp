// Polygons and capsules: the deepest point of a pair by GJK and EPA (gjk.h), then the
// candidates of the contact cache's tie rule read off the face that point pushes against.
//
// GJK gives the distance between the cores; the shapes touch when it is at most ρ1 + ρ2, with
//   n = (b − a)/|b − a|,  depth = ρ1 + ρ2 − |b − a|       (a, b the cores' closest points)
// When the cores overlap, EPA gives n and the cores' depth d, and depth = d + ρ1 + ρ2. The
// incident body's deepest point is its core's witness pushed in by its radius, b − ρ2 n.
// A flat landing has two equally deep points, as for boxes (box_box.cpp): when n is, to
// rounding, the outward normal m of a face of one body (the reference), the other body's core
// vertices v give candidates measured against that face (a point of it f):
//   point = v − ρ_inc m,  depth = ρ_ref + ρ_inc − m · (v − f)
// kept when the point lies inside the reference shape; the tie rule (narrow_phase.h) chooses,
// but for a first contact of several tied points: the box's midpoint of the tied ends becomes
// the point of their span under the incident body's centre of mass, x_inc projected along the
// face. One point there pushes through the centre and turns nothing; the midpoint of a
// triangle's base does not lie under its centroid, and turns it onto one corner far enough
// that the other corner leaves the ties (tests/test_box2d_comparison.cpp, the triangle).
#include <algorithm>
#include <limits>

#include "contact/narrow_phase.h"

namespace lamina {
namespace {

// n counts as a face's normal when their cosine is this close to 1: EPA's normal is an edge
// normal of the Minkowski difference, which is one of the two shapes' edge normals up to the
// rounding of a few differences (1e-15); a tilt of 4.5e-5 rad still counts.
constexpr double face_alignment = 1e-9;

// A face of a core: a point on it and its outward unit normal (a segment has two, a point none).
struct CoreFace {
  Vec2 point = Vec2::Zero();   // f, in m
  Vec2 normal = Vec2::UnitY(); // m, unit, outward
  double alignment = -std::numeric_limits<double>::infinity();  // m · (the direction asked)
};

// The face of a core whose outward normal is nearest to `direction`.
CoreFace best_face(const Convex& core, const Vec2& direction) {
  CoreFace best;
  const auto consider = [&](const Vec2& point, const Vec2& normal) {
    const double alignment = normal.dot(direction);
    if (alignment > best.alignment) best = CoreFace{point, normal, alignment};
  };
  if (core.count == 2) {
    const Vec2 edge = (core.vertices[1] - core.vertices[0]).normalized();
    consider(core.vertices[0], Vec2(edge.y(), -edge.x()));
    consider(core.vertices[0], Vec2(-edge.y(), edge.x()));
  } else if (core.count >= 3) {
    for (int i = 0; i < core.count; ++i) {
      const Vec2 edge = (core.vertices[(i + 1) % core.count] - core.vertices[i]).normalized();
      consider(core.vertices[i], Vec2(edge.y(), -edge.x()));  // counter-clockwise: outward is right
    }
  }
  return best;
}

// The candidates of a pair, at most every core vertex of both bodies; no allocation.
struct Candidates {
  std::array<Collision, 2 * Convex::max_vertices> items;  // the candidates found
  int count = 0;                                           // how many of items are valid
};

// On a first contact, the point of the tied candidates' span under `centre` (the incident body's
// centre of mass), with the depth interpolated along the span; nothing when fewer than two of
// the deepest one's reference tie.
std::optional<Collision> balanced_first_point(const Candidates& candidates, const Vec2& centre,
                                              const TieRule& ties) {
  int deepest = 0;
  for (int k = 1; k < candidates.count; ++k) {
    if (candidates.items[k].depth > candidates.items[deepest].depth) deepest = k;
  }
  const Collision& d = candidates.items[deepest];
  const Vec2 along = tangent_of(d.normal);
  const Collision* low = nullptr;   // the tied candidate farthest back along the face
  const Collision* high = nullptr;  // and the one farthest on
  for (int k = 0; k < candidates.count; ++k) {
    const Collision& c = candidates.items[k];
    if (c.reference != d.reference || c.depth < d.depth - ties.tolerance) continue;
    if (!low || along.dot(c.point) < along.dot(low->point)) low = &c;
    if (!high || along.dot(c.point) > along.dot(high->point)) high = &c;
  }
  const double span = along.dot(high->point - low->point);
  if (low == high || span <= 0.0) return std::nullopt;
  const double s = std::clamp(along.dot(centre - low->point) / span, 0.0, 1.0);
  Collision balanced = d;
  balanced.point = low->point + s * (high->point - low->point);
  balanced.depth = low->depth + s * (high->depth - low->depth);
  return balanced;
}

}  // namespace

std::optional<Collision> collide_convex(const Shape& shape1, const Pose2& pose1,
                                        const Shape& shape2, const Pose2& pose2,
                                        const CachedPoints& cached, const TieRule& ties) {
  const std::array<Convex, 2> cores{core_of(shape1, pose1), core_of(shape2, pose2)};
  const double reach = cores[0].radius + cores[1].radius;  // ρ1 + ρ2
  const GjkResult distance = gjk(cores[0], cores[1]);
  Collision deepest;
  if (!distance.overlap) {
    if (distance.distance > reach) return std::nullopt;
    deepest.normal = distance.normal;
    deepest.depth = reach - distance.distance;
    deepest.point = distance.point_b - cores[1].radius * deepest.normal;
  } else {
    const EpaResult penetration = epa(cores[0], cores[1], distance);
    deepest.normal = penetration.normal;
    deepest.depth = penetration.depth + reach;
    deepest.point = penetration.point_b - cores[1].radius * deepest.normal;
  }
  deepest.reference = 0;

  // The faces n is normal to: body 1's outward along n, body 2's outward along −n.
  const std::array<const Shape*, 2> shapes{&shape1, &shape2};
  const std::array<const Pose2*, 2> poses{&pose1, &pose2};
  Candidates candidates;
  for (int ref = 0; ref < 2; ++ref) {
    const Vec2 outward = ref == 0 ? deepest.normal : Vec2(-deepest.normal);
    const CoreFace face = best_face(cores[ref], outward);
    if (face.alignment < 1.0 - face_alignment) continue;
    const Convex& incident = cores[1 - ref];
    for (int v = 0; v < incident.count; ++v) {
      Collision c;
      c.point = incident.vertices[v] - incident.radius * face.normal;
      c.depth = reach - face.normal.dot(incident.vertices[v] - face.point);
      c.normal = ref == 0 ? face.normal : Vec2(-face.normal);
      c.reference = ref;
      if (contains(*shapes[ref], *poses[ref], c.point, containment_tolerance)) {
        candidates.items[candidates.count++] = c;
      }
    }
  }
  if (candidates.count == 0) return deepest;  // a corner against a corner, or a circle's round
  if (cached.count == 0 && ties.break_ties && ties.midpoint_first) {
    const Vec2& centre = candidates.items[0].reference == 0 ? pose2.x : pose1.x;
    if (std::optional<Collision> balanced = balanced_first_point(candidates, centre, ties)) {
      return balanced;
    }
  }
  return choose_deepest(candidates.items.data(), candidates.count, cached, ties);
}

}  // namespace lamina
