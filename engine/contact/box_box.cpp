// Box–box: the separating axis test, and the deepest vertex with the ties the literal
// "deepest point" gets wrong (docs/ch4-contact-model.md, "Beyond the text").
#include <algorithm>
#include <limits>

#include "contact/narrow_phase.h"

namespace lamina {
namespace {

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

// The other box's vertices measured against the reference box's faces.
struct FaceTable {
  std::array<std::array<double, 4>, 4> s;  // s[f][v] = n_f · (v − x_r) − h_f, in m (> 0: outside f)
  int best = 0;                            // the face of largest separation
  double separation = 0.0;                 // its s_f, in m (> 0: apart)
  Vec2 normal;                             // its n_f, world frame (the faces are not kept)

  // Vertex v lies inside the reference box, or outside by at most `tolerance`: on the inner
  // side of all four faces (contains() of shape.h, from the same numbers).
  bool contains(int v, double tolerance) const {
    return std::max({s[0][v], s[1][v], s[2][v], s[3][v]}) <= tolerance;
  }
  // How far vertex v is inside the best face: h_f − n_f · (v − x_r).
  double depth(int v) const { return -s[best][v]; }
};

FaceTable face_table(const Shape& box, const Pose2& pose, const std::array<Vec2, 4>& others) {
  const std::array<Face, 4> faces = faces_of(box, pose);
  FaceTable table;
  // the other box's vertices from this box's centre, v − x_r, as a row of x and a row of y, so
  // that each face's four products go two at a time
  std::array<double, 4> dx;
  std::array<double, 4> dy;
  for (int v = 0; v < 4; ++v) {
    dx[v] = others[v].x() - pose.x.x();
    dy[v] = others[v].y() - pose.x.y();
  }
  for (int f = 0; f < 4; ++f) {
    const double nx = faces[f].normal.x();
    const double ny = faces[f].normal.y();
    const double h = faces[f].offset;
    // s[f][v] = n_f · (v − x_r) − h_f
    for (int v = 0; v < 4; ++v) table.s[f][v] = (nx * dx[v] + ny * dy[v]) - h;
  }
  table.separation = -std::numeric_limits<double>::infinity();
  constexpr double none = std::numeric_limits<double>::infinity();
  for (int f = 0; f < 4; ++f) {
    // s_f = min over the other box's vertices, vertex after vertex from +∞ (written out: as a
    // loop it took a fifth of the table's instructions)
    const std::array<double, 4>& s = table.s[f];
    const double s_f = std::min(std::min(std::min(std::min(none, s[0]), s[1]), s[2]), s[3]);
    if (s_f > table.separation) {
      table.best = f;
      table.separation = s_f;
    }
  }
  table.normal = faces[table.best].normal;
  return table;
}

// The candidate points of a pair: at most the 4 vertices of each box; no allocation.
struct BoxCandidates {
  std::array<Collision, 8> items;  // the candidates found
  int count = 0;                   // how many of items are valid

  void add(const Collision& c) { items[count++] = c; }
};

}  // namespace

std::optional<Collision> collide_boxes(const Shape& box1, const Pose2& pose1, const Shape& box2,
                                       const Pose2& pose2, const CachedPoints& cached,
                                       const TieRule& ties) {
  // Separating axis test over both boxes' face normals: body 1's faces against body 2's
  // vertices and the other way round; a separating axis among body 1's faces ends it early.
  const std::array<Vec2, 4> corners2 = vertices_of(box2, pose2);
  const FaceTable table1 = face_table(box1, pose1, corners2);
  if (table1.separation > 0.0) return std::nullopt;  // apart (0 is touching)
  const std::array<Vec2, 4> corners1 = vertices_of(box1, pose1);
  const FaceTable table2 = face_table(box2, pose2, corners1);
  const double separation = std::max(table1.separation, table2.separation);
  if (separation > 0.0) return std::nullopt;
  const std::array<const FaceTable*, 2> tables{&table1, &table2};

  // Candidates: the incident vertices inside the reference box, trying both boxes as the
  // reference when their faces separate equally (a box resting half over another has one
  // supported vertex of its own and one of the box below) — when ties are broken.
  const double tie_tolerance = ties.break_ties ? ties.tolerance : 0.0;
  const std::array<const std::array<Vec2, 4>*, 2> corners{&corners1, &corners2};
  const auto candidate = [&](int ref, int v) {
    const FaceTable& table = *tables[ref];
    Collision c;
    c.point = (*corners[1 - ref])[v];
    c.depth = table.depth(v);
    // n points from body 1 to body 2: body 1's outward face normal, or body 2's reversed.
    const Vec2& normal = table.normal;
    c.normal = ref == 0 ? normal : Vec2(-normal);
    c.reference = ref;
    return c;
  };
  BoxCandidates candidates;
  for (int ref = 0; ref < 2; ++ref) {
    if (tables[ref]->separation < separation - tie_tolerance) continue;
    for (int v = 0; v < 4; ++v) {
      if (tables[ref]->contains(v, containment_tolerance)) candidates.add(candidate(ref, v));
    }
  }
  if (candidates.count == 0) {
    // Two boxes crossing like a plus sign overlap with no vertex inside the other: return the
    // incident vertex deepest past the separating-axis face.
    const int ref = table1.separation >= table2.separation ? 0 : 1;
    int deepest = 0;
    for (int v = 1; v < 4; ++v) {
      if (tables[ref]->depth(v) > tables[ref]->depth(deepest)) deepest = v;
    }
    return candidate(ref, deepest);
  }
  return choose_deepest(candidates.items.data(), candidates.count, cached, ties);
}

}  // namespace lamina
