// GJK and EPA (beyond the text, which leaves them to van den Bergen and Ericson): GJK's distance
// and closest points against brute force on random convex pairs, EPA's depth and normal against
// the separating axis test, the degenerate inputs each must survive, and the recorded iterations.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "contact/gjk.h"

using namespace lamina;

namespace {

// The random pairs are a few rotations and additions of metre-sized coordinates: GJK's simplex
// arithmetic and the brute force agree to a few ulps of 10 m, far inside this.
constexpr double near = 1e-9;  // in m

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

Pose2 pose(double x, double y, double angle) {
  Pose2 p;
  p.x = Vec2(x, y);
  p.R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return p;
}

Convex convex(const std::vector<Vec2>& vertices) {
  Convex c;
  for (const Vec2& v : vertices) c.vertices[c.count++] = v;
  return c;
}

Convex box(double hx, double hy, const Vec2& centre = Vec2::Zero()) {
  return convex({centre + Vec2(-hx, -hy), centre + Vec2(hx, -hy), centre + Vec2(hx, hy),
                 centre + Vec2(-hx, hy)});
}

Convex moved(Convex c, const Vec2& by) {
  for (int i = 0; i < c.count; ++i) c.vertices[i] += by;
  return c;
}

// A point (1 in 10), a segment (1 in 10) or a polygon of 3..8 vertices at sorted random angles on
// an ellipse (so convex and counter-clockwise), at a random pose within `spread` of the origin.
Convex random_convex(std::mt19937& rng, double spread, bool polygon_only = false) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int kind = std::uniform_int_distribution<int>(0, 9)(rng);
  const int count = polygon_only || kind >= 2 ? std::uniform_int_distribution<int>(3, 8)(rng)
                                              : kind + 1;
  const double rx = 0.2 + 1.3 * unit(rng), ry = 0.2 + 1.3 * unit(rng);
  std::vector<double> angles;
  while (static_cast<int>(angles.size()) < count) {
    angles.assign(count, 0.0);
    for (double& t : angles) t = 2.0 * M_PI * unit(rng);
    std::sort(angles.begin(), angles.end());
    for (int i = 0; i + 1 < count; ++i)  // vertices well apart: no near-duplicates
      if (angles[i + 1] - angles[i] < 0.05) angles.clear();
    if (!angles.empty() && angles.front() + 2.0 * M_PI - angles.back() < 0.05) angles.clear();
  }
  const Pose2 p = pose(spread * (2.0 * unit(rng) - 1.0), spread * (2.0 * unit(rng) - 1.0),
                       2.0 * M_PI * unit(rng));
  Convex c;
  for (double t : angles)
    c.vertices[c.count++] = p.to_world(Vec2(rx * std::cos(t), ry * std::sin(t)));
  return c;
}

// The edges of a core: a closed loop for a polygon, one edge for a segment, (p, p) for a point.
std::vector<std::pair<Vec2, Vec2>> edges(const Convex& c) {
  if (c.count <= 2) return {{c.vertices[0], c.vertices[c.count - 1]}};
  std::vector<std::pair<Vec2, Vec2>> e;
  for (int i = 0; i < c.count; ++i) e.push_back({c.vertices[i], c.vertices[(i + 1) % c.count]});
  return e;
}

double point_segment_distance(const Vec2& p, const Vec2& q0, const Vec2& q1) {
  const Vec2 e = q1 - q0;
  const double t =
      e.squaredNorm() > 0.0 ? std::clamp((p - q0).dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (q0 + t * e)).norm();
}

// Segments meet when each one's ends are not strictly on one side of the other (a crossing), or
// an end lies on the other segment (touching, collinear overlap, points).
bool segments_meet(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const double a = cross(p1 - p0, q0 - p0), b = cross(p1 - p0, q1 - p0);
  const double c = cross(q1 - q0, p0 - q0), d = cross(q1 - q0, p1 - q0);
  if (((a > 0 && b < 0) || (a < 0 && b > 0)) && ((c > 0 && d < 0) || (c < 0 && d > 0))) return true;
  return point_segment_distance(q0, p0, p1) == 0.0 || point_segment_distance(q1, p0, p1) == 0.0 ||
         point_segment_distance(p0, q0, q1) == 0.0 || point_segment_distance(p1, q0, q1) == 0.0;
}

// A point is inside a counter-clockwise polygon when it is on the inner side of every edge.
bool inside(const Convex& c, const Vec2& p) {
  if (c.count < 3) return false;
  for (const auto& [v0, v1] : edges(c))
    if (cross(v1 - v0, p - v0) < 0.0) return false;
  return true;
}

bool overlap_brute(const Convex& a, const Convex& b) {
  if (inside(a, b.vertices[0]) || inside(b, a.vertices[0])) return true;
  for (const auto& [p0, p1] : edges(a))
    for (const auto& [q0, q1] : edges(b))
      if (segments_meet(p0, p1, q0, q1)) return true;
  return false;
}

// Apart, the cores are nearest between a vertex of one and an edge of the other.
double distance_brute(const Convex& a, const Convex& b) {
  if (overlap_brute(a, b)) return 0.0;
  double best = INFINITY;
  for (const auto& [p0, p1] : edges(a))
    for (const auto& [q0, q1] : edges(b))
      best = std::min({best, point_segment_distance(p0, q0, q1), point_segment_distance(p1, q0, q1),
                       point_segment_distance(q0, p0, p1), point_segment_distance(q1, p0, p1)});
  return best;
}

double boundary_distance(const Convex& c, const Vec2& p) {
  double best = INFINITY;
  for (const auto& [v0, v1] : edges(c)) best = std::min(best, point_segment_distance(p, v0, v1));
  return best;
}

// The separating axis test: over every edge normal u of either polygon, both ways, moving B by
// (max_A u · a − min_B u · b) along u separates them; the least such push is the depth.
struct Axis {
  Vec2 normal = Vec2::UnitY();
  double depth = INFINITY;
};

struct SatDepth {
  Axis best, runner_up;  // the runner-up along a different direction
};

SatDepth sat_depth(const Convex& a, const Convex& b) {
  std::vector<Axis> axes;
  for (const Convex* c : {&a, &b})
    for (const auto& [v0, v1] : edges(*c)) {
      const Vec2 u = Vec2((v1 - v0).y(), -(v1 - v0).x()).normalized();
      for (const Vec2& n : {u, Vec2(-u)}) {
        double max_a = -INFINITY, min_b = INFINITY;
        for (int i = 0; i < a.count; ++i) max_a = std::max(max_a, n.dot(a.vertices[i]));
        for (int i = 0; i < b.count; ++i) min_b = std::min(min_b, n.dot(b.vertices[i]));
        axes.push_back({n, max_a - min_b});
      }
    }
  SatDepth sat;
  for (const Axis& axis : axes)
    if (axis.depth < sat.best.depth) sat.best = axis;
  for (const Axis& axis : axes)
    if ((axis.normal - sat.best.normal).norm() > 1e-6 && axis.depth < sat.runner_up.depth)
      sat.runner_up = axis;
  return sat;
}

bool finite(const GjkResult& r) {
  return std::isfinite(r.distance) && r.point_a.allFinite() && r.point_b.allFinite() &&
         r.normal.allFinite();
}

bool finite(const EpaResult& r) {
  return std::isfinite(r.depth) && r.point_a.allFinite() && r.point_b.allFinite() &&
         r.normal.allFinite() && std::abs(r.normal.norm() - 1.0) <= 1e-12;
}

// A unit normal along ±x or ±y, to rounding (1e-12): which one is a tie between a square's faces.
bool on_an_axis(const Vec2& n) {
  return std::abs(std::max(std::abs(n.x()), std::abs(n.y())) - 1.0) <= 1e-12;
}

// GJK's distance, 0 when it reports the cores overlapping or touching.
double gjk_distance(const Convex& a, const Convex& b) {
  const GjkResult r = gjk(a, b);
  return r.overlap ? 0.0 : r.distance;
}

// GJK then EPA on an overlapping pair, without NaN, each within `gjk_bound` and `epa_bound`
// iterations: the counts these exact inputs take (both are deterministic), well under the
// maxima of 32.
EpaResult penetration(const Convex& a, const Convex& b, int gjk_bound, int epa_bound) {
  const GjkResult g = gjk(a, b);
  REQUIRE(g.overlap);
  CHECK(g.iterations <= gjk_bound);
  CHECK(finite(g));
  const EpaResult e = epa(a, b, g);
  CHECK(e.iterations <= epa_bound);
  CHECK(finite(e));
  return e;
}

}  // namespace

TEST_SUITE("GJK and EPA") {
  TEST_CASE("GJK's distance and closest points match brute force on random convex pairs") {
    std::mt19937 rng(20240611);
    int apart = 0, overlapping = 0, most_iterations = 0;
    for (int pair = 0; pair < 4000; ++pair) {
      CAPTURE(pair);
      const Convex a = random_convex(rng, 1.0), b = random_convex(rng, 1.0);
      const GjkResult r = gjk(a, b);
      const double brute = distance_brute(a, b);
      most_iterations = std::max(most_iterations, r.iterations);
      CHECK(finite(r));
      // Brute force and GJK both to rounding of metre-sized coordinates (`near`).
      CHECK(std::abs((r.overlap ? 0.0 : r.distance) - brute) <= near);
      if (r.overlap) {
        ++overlapping;
        continue;
      }
      ++apart;
      // The closest points are the distance apart, and each on its core's boundary (`near`).
      CHECK(std::abs((r.point_b - r.point_a).norm() - r.distance) <= near);
      CHECK(boundary_distance(a, r.point_a) <= near);
      CHECK(boundary_distance(b, r.point_b) <= near);
      CHECK(r.normal.isApprox((r.point_b - r.point_a) / r.distance, near));
    }
    // Both kinds of pair were drawn in numbers; no pair needed more than a handful of support
    // points (6 on this seed; GJK never asks twice for one of D's at most 64 vertex pairs).
    CHECK(apart > 1000);
    CHECK(overlapping > 1000);
    CHECK(most_iterations <= 8);
  }

  TEST_CASE("EPA's depth and normal are the separating axis test's, and moving B by them touches") {
    std::mt19937 rng(7);
    int pairs = 0, unique_axes = 0, most_iterations = 0;
    while (pairs < 2000) {
      const Convex a = random_convex(rng, 1.0, true), b = random_convex(rng, 1.0, true);
      const SatDepth sat = sat_depth(a, b);
      if (sat.best.depth < 1e-6) continue;  // apart or only just touching: not this test's
      ++pairs;
      CAPTURE(pairs);
      const GjkResult g = gjk(a, b);
      REQUIRE(g.overlap);
      const EpaResult e = epa(a, b, g);
      most_iterations = std::max(most_iterations, e.iterations);
      // SAT is exact for convex polygons in 2D; both to rounding of metre-sized coordinates.
      CHECK(std::abs(e.depth - sat.best.depth) <= near);
      if (sat.runner_up.depth - sat.best.depth > 1e-6) {  // one least axis, by a margin
        ++unique_axes;
        CHECK((e.normal - sat.best.normal).norm() <= near);
      }
      // The witnesses lie on the cores' boundaries, depth apart along n (rounding, `near`).
      CHECK(boundary_distance(a, e.point_a) <= near);
      CHECK(boundary_distance(b, e.point_b) <= near);
      CHECK((e.point_a - e.depth * e.normal - e.point_b).norm() <= near);
      // B moved by depth·n touches A; by another 1 µm it is 1 µm away (rounding, `near`).
      CHECK(gjk_distance(a, moved(b, e.depth * e.normal)) <= near);
      CHECK(std::abs(gjk_distance(a, moved(b, (e.depth + 1e-6) * e.normal)) - 1e-6) <= near);
    }
    CHECK(unique_axes > 1500);
    CHECK(most_iterations <= 12);  // 8 on this seed; D has at most 16 vertices
  }

  TEST_CASE("degenerate pairs end within a few iterations with finite answers") {
    const Convex square = box(0.5, 0.5);
    SUBCASE("touching at a vertex: depth 0 along one of the two faces") {
      const EpaResult e = penetration(square, box(0.5, 0.5, Vec2(1.0, 1.0)), 2, 3);
      CHECK(e.depth <= 1e-15);  // exact inputs: rounding only
      CHECK((e.normal.isApprox(Vec2::UnitX(), 1e-12) || e.normal.isApprox(Vec2::UnitY(), 1e-12)));
    }
    SUBCASE("touching along an edge: depth 0, n = +x") {
      const EpaResult e = penetration(square, box(0.5, 0.25, Vec2(1.0, 0.2)), 3, 2);
      CHECK(e.depth <= 1e-15);  // exact inputs: rounding only
      CHECK(e.normal.isApprox(Vec2::UnitX(), 1e-12));
    }
    SUBCASE("identical shapes: the depth is the square's width") {
      const EpaResult e = penetration(square, square, 1, 5);
      CHECK(std::abs(e.depth - 1.0) <= 1e-12);  // exact inputs: rounding only
      CHECK(on_an_axis(e.normal));
    }
    SUBCASE("one nested inside the other: pushed out through the nearest face") {
      // The inner square spans x ∈ [0.5, 1.5]; the outer one's face x = 2 is 1.5 away.
      const EpaResult e = penetration(box(2.0, 2.0), box(0.5, 0.5, Vec2(1.0, 0.2)), 3, 3);
      CHECK(std::abs(e.depth - 1.5) <= 1e-12);  // exact inputs: rounding only
      CHECK(e.normal.isApprox(Vec2::UnitX(), 1e-12));
    }
    SUBCASE("a point at a square's centre leaves through a face, half the width away") {
      const EpaResult e = penetration(square, convex({Vec2::Zero()}), 2, 3);
      CHECK(std::abs(e.depth - 0.5) <= 1e-12);  // exact inputs: rounding only
      CHECK(on_an_axis(e.normal));
    }
    SUBCASE("a point on a square's edge touches it: depth 0, n = +x") {
      const EpaResult e = penetration(square, convex({Vec2(0.5, 0.3)}), 3, 2);
      CHECK(e.depth <= 1e-15);  // exact inputs: rounding only
      CHECK(e.normal.isApprox(Vec2::UnitX(), 1e-12));
    }
    SUBCASE("two collinear overlapping segments: D has no area, depth 0 across the line") {
      const EpaResult e =
          penetration(convex({Vec2(0, 0), Vec2(2, 0)}), convex({Vec2(1, 0), Vec2(3, 0)}), 2, 0);
      CHECK(e.depth == 0.0);  // no area: exactly
      CHECK(std::abs(e.normal.y()) == doctest::Approx(1.0).epsilon(1e-12));
      CHECK(e.point_a.y() == 0.0);  // on the segments' line: exactly
    }
    SUBCASE("a 1 cm segment along another, 1 km out: GJK stops on the point it just dropped") {
      // Rounding at 1 km (an ulp is 1.1e-13 m) leaves D a sliver; GJK's triangle falls back to
      // the same edge every time, and only the repeated vertex pair ends the search.
      for (double angle : {0.015, 0.018, 0.024, 0.033, 0.042}) {
        CAPTURE(angle);
        const Vec2 base(1000.0, 1000.0), along(0.01 * std::cos(angle), 0.01 * std::sin(angle));
        const Convex a = convex({base, base + along});
        const Convex b = convex({base + 0.4 * along, base + 0.7 * along});
        const GjkResult g = gjk(a, b);
        CHECK(g.iterations <= 3);
        CHECK(finite(g));
        CHECK(gjk_distance(a, b) <= 1e-12);  // a few ulps of 1 km
      }
    }
    SUBCASE("a segment across a square leaves through the nearer side") {
      // The segment x = 0.2 is 0.3 from the face x = 0.5 and 0.7 from x = −0.5.
      const EpaResult e = penetration(square, convex({Vec2(0.2, -3.0), Vec2(0.2, 3.0)}), 3, 3);
      CHECK(std::abs(e.depth - 0.3) <= 1e-12);  // exact inputs: rounding only
      CHECK(e.normal.isApprox(Vec2::UnitX(), 1e-12));
    }
    SUBCASE("far apart: 1 km between a square and a triangle") {
      const Convex far_triangle = convex({Vec2(1000.5, 0), Vec2(1001.5, 0), Vec2(1001.0, 1.0)});
      const GjkResult g = gjk(square, far_triangle);
      CHECK_FALSE(g.overlap);
      CHECK(g.iterations <= 3);
      CHECK(std::abs(g.distance - 1000.0) <= 1e-9);  // rounding of km coordinates
      CHECK(g.normal.isApprox(Vec2::UnitX(), 1e-12));
      // The same overlapping pair 1 km from the origin: depth 0.1 to rounding of 1e3 (1e-12 m).
      const Vec2 km(1000.0, 1000.0);
      const EpaResult e = penetration(moved(square, km), box(0.5, 0.5, km + Vec2(0.9, 0.3)), 3, 2);
      CHECK(std::abs(e.depth - 0.1) <= 1e-12);
      CHECK(e.normal.isApprox(Vec2::UnitX(), 1e-12));
    }
    SUBCASE("tiny: millimetre squares apart by and overlapping by 0.1 mm") {
      const Convex mm = box(5e-4, 5e-4);
      const GjkResult g = gjk(mm, box(5e-4, 5e-4, Vec2(1.1e-3, 0.0)));
      CHECK_FALSE(g.overlap);
      CHECK(g.iterations <= 3);
      CHECK(std::abs(g.distance - 1e-4) <= 1e-15);  // rounding of millimetres
      const EpaResult e = penetration(mm, box(5e-4, 5e-4, Vec2(0.0, 0.9e-3)), 3, 2);
      CHECK(std::abs(e.depth - 1e-4) <= 1e-15);  // rounding of millimetres
      CHECK(e.normal.isApprox(Vec2::UnitY(), 1e-12));
    }
  }

  TEST_CASE("the record has an entry per iteration; an overlap ends on a triangle around the origin") {
    const Convex triangle = convex({Vec2(-1.0, -0.5), Vec2(1.0, -0.5), Vec2(0.0, 1.0)});
    const Convex square = box(0.4, 0.4, Vec2(0.3, 0.6));
    std::vector<GjkIteration> gjk_record;
    const GjkResult g = gjk(triangle, square, &gjk_record);
    REQUIRE(g.overlap);
    CHECK(static_cast<int>(gjk_record.size()) == g.iterations);
    REQUIRE(g.simplex.count == 3);
    // The origin is on the inner side of all three edges, or on one (cross ≥ 0, exact sign).
    const Vec2 w0 = g.simplex.points[0].w, w1 = g.simplex.points[1].w, w2 = g.simplex.points[2].w;
    const double turn = cross(w1 - w0, w2 - w0) > 0.0 ? 1.0 : -1.0;
    CHECK(turn * cross(w1 - w0, -w0) >= 0.0);
    CHECK(turn * cross(w2 - w1, -w1) >= 0.0);
    CHECK(turn * cross(w0 - w2, -w2) >= 0.0);
    // Each recorded support point is s_D along the recorded direction −closest/|closest|.
    for (const GjkIteration& it : gjk_record) {
      CHECK(it.direction.isApprox(-it.closest.normalized(), 1e-15));  // the same arithmetic
      CHECK(it.support.w == it.support.b - it.support.a);
    }
    std::vector<EpaIteration> epa_record;
    const EpaResult e = epa(triangle, square, g, &epa_record);
    CHECK(static_cast<int>(epa_record.size()) == e.iterations);
    REQUIRE_FALSE(epa_record.empty());
    // The last iteration's nearest edge is the answer: n = −m, depth its distance (exact copies).
    CHECK(e.normal == -epa_record.back().normal);
    CHECK(e.depth == std::max(0.0, epa_record.back().distance));
    // Apart, GJK records too, and stops by itself without a triangle.
    std::vector<GjkIteration> apart_record;
    const GjkResult apart = gjk(triangle, moved(square, Vec2(3.0, 0.0)), &apart_record);
    CHECK_FALSE(apart.overlap);
    CHECK(static_cast<int>(apart_record.size()) == apart.iterations);
    CHECK(apart.simplex.count <= 2);
  }
}
