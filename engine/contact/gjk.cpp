// GJK and EPA in the plane: the method and the notation are in gjk.h. Every array here has a fixed
// size, so neither function touches the heap unless it is asked to record its iterations.
#include "contact/gjk.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lamina {

namespace {

// GJK stops when the new support point s brings it no nearer: w · w − w · s ≤ ε |w|².
constexpr double gjk_progress = 1e-10;
// GJK's closest point w is the origin (the cores touch) when |w| ≤ this times the simplex's
// largest |w_i|: what the rounding of the closest-point arithmetic leaves of an exact zero.
constexpr double gjk_touching = 1e-12;
// EPA stops when the support point s is no farther out than the nearest edge:
// n · s − distance ≤ ε max(1, distance), distance in m.
constexpr double epa_progress = 1e-10;
// Below this sine of the angle between two of D's chords, EPA's first triangle has no area.
constexpr double epa_flat = 1e-12;

// The barycentric weights λ_i of the simplex's point nearest the origin, w = Σ λ_i w_i.
using Weights = std::array<double, 3>;

// EPA's polygon: D's points found so far, counter-clockwise. It starts with at most 3 and gains
// at most one for each support point asked for.
struct Polytope {
  std::array<SimplexVertex, 3 + epa_max_iterations> points{};
  int count = 0;
};

// The edge (points[index], points[index + 1]) of the polytope nearest the origin.
struct Edge {
  int index = 0;
  Vec2 outward = Vec2::UnitY();  // the edge's outward unit normal m
  double distance = 0.0;         // m · w of its points: its distance from the origin, in m
};

// u × v, the z component of the 3D cross product: twice the signed area of (0, u, v).
double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

// s_D(d) = s_B(d) − s_A(−d): the point of D = B − A farthest along d, with its two vertices.
SimplexVertex support_point(const Convex& a, const Convex& b, const Vec2& d) {
  SimplexVertex v;
  v.index_a = a.support(-d);
  v.index_b = b.support(d);
  v.a = a.vertices[v.index_a];
  v.b = b.vertices[v.index_b];
  v.w = v.b - v.a;
  return v;
}

// Whether the same pair of vertices (hence the same point of D) is among the first `count`.
bool holds(const SimplexVertex* points, int count, const SimplexVertex& v) {
  return std::any_of(points, points + count, [&](const SimplexVertex& p) {
    return p.index_a == v.index_a && p.index_b == v.index_b;
  });
}

// The simplex cut down to its vertex i: the origin is in that vertex's Voronoi region.
void keep_vertex(Simplex& s, Weights& weights, int i) {
  s.points[0] = s.points[i];
  s.count = 1;
  weights = {1.0, 0.0, 0.0};
}

// The simplex cut down to its edge (i, j), the origin's projection having the unnormalised
// weights u_i, u_j > 0.
void keep_edge(Simplex& s, Weights& weights, int i, int j, double u_i, double u_j) {
  const SimplexVertex p = s.points[i], q = s.points[j];
  s.points[0] = p;
  s.points[1] = q;
  s.count = 2;
  weights = {u_i / (u_i + u_j), u_j / (u_i + u_j), 0.0};
}

// The segment's point nearest the origin. With e = w2 − w1 the origin projects to
// λ1 = w2 · e / e · e and λ2 = −w1 · e / e · e; each numerator is a dot product of a vertex
// with e (no difference of nearly equal weights), and one of them ≤ 0 means the origin lies
// beyond the other vertex, in that vertex's region.
void solve_segment(Simplex& s, Weights& weights) {
  const Vec2 w1 = s.points[0].w, w2 = s.points[1].w;
  const Vec2 e = w2 - w1;
  const double u1 = w2.dot(e), u2 = -w1.dot(e);
  if (u2 <= 0.0) return keep_vertex(s, weights, 0);
  if (u1 <= 0.0) return keep_vertex(s, weights, 1);
  keep_edge(s, weights, 0, 1, u1, u2);
}

// The triangle's point nearest the origin, by its Voronoi regions. On each edge (i, j) the
// segment's numerators u_ij_i, u_ij_j as above; over the whole triangle the barycentric weights
// of the origin times the doubled area k = (w2 − w1) × (w3 − w1), squared to keep their sign:
// v1 = k (w2 × w3), v2 = k (w3 × w1), v3 = k (w1 × w2). A vertex's region: both its edges put
// the origin beyond it. An edge's region: the origin projects inside it and lies outside the
// triangle across it (the opposite vertex's v ≤ 0). Otherwise the origin is inside.
void solve_triangle(Simplex& s, Weights& weights) {
  const Vec2 w1 = s.points[0].w, w2 = s.points[1].w, w3 = s.points[2].w;
  const Vec2 e12 = w2 - w1, e13 = w3 - w1, e23 = w3 - w2;
  const double u12_1 = w2.dot(e12), u12_2 = -w1.dot(e12);
  const double u13_1 = w3.dot(e13), u13_3 = -w1.dot(e13);
  const double u23_2 = w3.dot(e23), u23_3 = -w2.dot(e23);
  const double k = cross(e12, e13);
  const double v1 = k * cross(w2, w3), v2 = k * cross(w3, w1), v3 = k * cross(w1, w2);
  if (u12_2 <= 0.0 && u13_3 <= 0.0) return keep_vertex(s, weights, 0);
  if (u12_1 > 0.0 && u12_2 > 0.0 && v3 <= 0.0) return keep_edge(s, weights, 0, 1, u12_1, u12_2);
  if (u13_1 > 0.0 && u13_3 > 0.0 && v2 <= 0.0) return keep_edge(s, weights, 0, 2, u13_1, u13_3);
  if (u12_1 <= 0.0 && u23_3 <= 0.0) return keep_vertex(s, weights, 1);
  if (u13_1 <= 0.0 && u23_2 <= 0.0) return keep_vertex(s, weights, 2);
  if (u23_2 > 0.0 && u23_3 > 0.0 && v1 <= 0.0) return keep_edge(s, weights, 1, 2, u23_2, u23_3);
  const double sum = v1 + v2 + v3;  // k², positive: a flat triangle ends in a region above
  assert(sum > 0.0);
  weights = {v1 / sum, v2 / sum, v3 / sum};
}

// GJK's reduction: the simplex's point nearest the origin and the fewest points that hold it.
void reduce(Simplex& s, Weights& weights) {
  if (s.count == 1) weights = {1.0, 0.0, 0.0};
  if (s.count == 2) solve_segment(s, weights);
  if (s.count == 3) solve_triangle(s, weights);
}

// Σ λ_i p_i of one part (a, b or w) of the simplex's points.
Vec2 combine(const Simplex& s, const Weights& weights, Vec2 SimplexVertex::*part) {
  Vec2 sum = Vec2::Zero();
  for (int i = 0; i < s.count; ++i) sum += weights[i] * (s.points[i].*part);
  return sum;
}

// The closest point w is the origin, to the rounding of the simplex's coordinates.
bool at_origin(const Simplex& s, const Vec2& w) {
  double largest = 0.0;
  for (int i = 0; i < s.count; ++i) largest = std::max(largest, s.points[i].w.squaredNorm());
  return w.squaredNorm() <= gjk_touching * gjk_touching * largest;
}

// The support point s along −w comes no nearer the origin than w: w · w − w · s ≤ ε |w|².
bool no_progress(const Vec2& w, const Vec2& s) {
  return w.squaredNorm() - w.dot(s) <= gjk_progress * w.squaredNorm();
}

// The polytope's edge nearest the origin (the first on a tie). Counter-clockwise, an edge
// e = w_k+1 − w_k has outward normal m = (e_y, −e_x)/|e| and lies at distance m · w_k.
Edge nearest_edge(const Polytope& p) {
  Edge best;
  best.distance = INFINITY;
  for (int k = 0; k < p.count; ++k) {
    const Vec2& w0 = p.points[k].w;
    const Vec2 e = p.points[(k + 1) % p.count].w - w0;
    assert(e.squaredNorm() > 0.0);
    const Vec2 m = Vec2(e.y(), -e.x()).normalized();
    if (m.dot(w0) < best.distance) best = Edge{k, m, m.dot(w0)};
  }
  return best;
}

// Drops the polytope's vertices that do not turn left (reflex or on a line), leaving the convex
// hull: after a point outside one edge is put into it, its neighbours may have become reflex.
void drop_reflex(Polytope& p) {
  for (int k = 0; k < p.count && p.count > 3;) {
    const Vec2& before = p.points[(k + p.count - 1) % p.count].w;
    const Vec2& here = p.points[k].w;
    const Vec2& after = p.points[(k + 1) % p.count].w;
    if (cross(here - before, after - here) > 0.0) {
      ++k;
      continue;
    }
    std::copy(p.points.begin() + k + 1, p.points.begin() + p.count, p.points.begin() + k);
    --p.count;
    k = 0;
  }
}

// Puts the support point v into the polytope between the ends of edge k.
void insert_after(Polytope& p, int k, const SimplexVertex& v) {
  assert(p.count < static_cast<int>(p.points.size()));
  std::copy_backward(p.points.begin() + k + 1, p.points.begin() + p.count,
                     p.points.begin() + p.count + 1);
  p.points[k + 1] = v;
  ++p.count;
  drop_reflex(p);
}

// Adds the first support point along `directions` that stands off the polytope's points: apart
// from a lone point, or off the line of two (the sine of the angle at points[0] above epa_flat).
void add_off_point(const Convex& a, const Convex& b, Polytope& p,
                   std::initializer_list<Vec2> directions) {
  const Vec2 w0 = p.points[0].w;
  const Vec2 e = p.count == 2 ? Vec2(p.points[1].w - w0) : Vec2::Zero();
  for (const Vec2& d : directions) {
    const SimplexVertex v = support_point(a, b, d);
    const Vec2 f = v.w - w0;
    const bool off = p.count == 1 ? f.norm() > epa_flat * std::max(w0.norm(), v.w.norm())
                                  : std::abs(cross(e, f)) > epa_flat * e.norm() * f.norm();
    if (off) {
      p.points[p.count++] = v;
      return;
    }
  }
}

// EPA's first polygon, from GJK's final simplex. A triangle holds the origin already. A touching
// simplex (a point or a segment with the origin on it) is grown with support points: along ±x
// and ±y from a point, then along the perpendiculars ±(−e_y, e_x) of the segment e. If D has no
// area (a point or a segment) the polytope stays a point or a segment. Counter-clockwise.
Polytope first_polygon(const Convex& a, const Convex& b, const Simplex& s) {
  Polytope p;
  std::copy(s.points.begin(), s.points.begin() + s.count, p.points.begin());
  p.count = s.count;
  if (p.count == 1)
    add_off_point(a, b, p, {Vec2::UnitX(), -Vec2::UnitX(), Vec2::UnitY(), -Vec2::UnitY()});
  if (p.count == 2) {
    const Vec2 across = tangent_of(p.points[1].w - p.points[0].w);
    add_off_point(a, b, p, {across, Vec2(-across)});
  }
  if (p.count == 3 && cross(p.points[1].w - p.points[0].w, p.points[2].w - p.points[0].w) < 0.0)
    std::swap(p.points[1], p.points[2]);
  return p;
}

// The origin's projection onto the segment from p to q, as the weight t of q (clamped to it).
double projection_weight(const SimplexVertex& p, const SimplexVertex& q) {
  const Vec2 e = q.w - p.w;
  return e.squaredNorm() > 0.0 ? std::clamp(-p.w.dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
}

// D without area: a segment (or a point) through the origin. Moving B off its line by any
// amount separates the cores, so the depth is 0 along the segment's perpendicular (+y for a
// point); the witness is the origin's place on the segment.
EpaResult flat_result(const Polytope& p) {
  EpaResult result;
  const SimplexVertex& p0 = p.points[0];
  const SimplexVertex& p1 = p.points[p.count - 1];
  const double t = projection_weight(p0, p1);
  if (p.count == 2) result.normal = tangent_of(p1.w - p0.w).normalized();
  result.point_a = p0.a + t * (p1.a - p0.a);
  result.point_b = result.point_a;
  return result;
}

// The penetration from the nearest edge (w0, w1) with outward normal m at distance d: the
// origin's nearest point of D is d m = b − a, so B moved by d along n = −m only touches A. The
// witness on A is the edge's a parts weighted as the origin projects onto the edge.
EpaResult penetration(const Polytope& p, const Edge& edge, int iterations) {
  const SimplexVertex& p0 = p.points[edge.index];
  const SimplexVertex& p1 = p.points[(edge.index + 1) % p.count];
  const double t = projection_weight(p0, p1);
  EpaResult result;
  result.normal = -edge.outward;
  result.depth = std::max(0.0, edge.distance);
  result.point_a = p0.a + t * (p1.a - p0.a);
  result.point_b = result.point_a - result.depth * result.normal;
  result.iterations = iterations;
  return result;
}

// What EPA's tutorial draws of one iteration.
EpaIteration epa_iteration(const Polytope& p, const Edge& edge, const Vec2& support) {
  EpaIteration it;
  for (int k = 0; k < p.count; ++k) it.polytope.push_back(p.points[k].w);
  it.nearest_edge = edge.index;
  it.normal = edge.outward;
  it.distance = edge.distance;
  it.support = support;
  return it;
}

}  // namespace

// The vertex maximising d · v, by a scan that only a strictly larger d · v overtakes.
int Convex::support(const Vec2& d) const {
  assert(count >= 1 && count <= max_vertices);
  int best = 0;
  double farthest = d.dot(vertices[0]);  // d · v of the best vertex so far
  for (int i = 1; i < count; ++i) {
    if (d.dot(vertices[i]) > farthest) {
      best = i;
      farthest = d.dot(vertices[i]);
    }
  }
  return best;
}

// GJK from the point w = b_0 − a_0 of D. Each iteration reduces the simplex to the fewest points
// holding its point w nearest the origin, stops if that is a triangle around the origin or w is
// the origin (overlap), else asks for s = s_D(−w/|w|) and stops when s brings no progress or is
// a point already in the simplex before its reduction (asked for again, a point the reduction
// dropped would be dropped again, for ever); otherwise s joins the simplex. The closest points
// are the simplex's a and b parts weighted as w is: w = Σ λ_i w_i = Σ λ_i b_i − Σ λ_i a_i.
GjkResult gjk(const Convex& a, const Convex& b, std::vector<GjkIteration>* record) {
  GjkResult result;
  Simplex& s = result.simplex;
  s.points[0] = SimplexVertex{a.vertices[0], b.vertices[0], b.vertices[0] - a.vertices[0], 0, 0};
  s.count = 1;
  Weights weights{};
  for (;;) {
    const Simplex unreduced = s;  // with any point the reduction drops: asked again, it ends GJK
    reduce(s, weights);
    const Vec2 closest = combine(s, weights, &SimplexVertex::w);
    result.overlap = s.count == 3 || at_origin(s, closest);
    if (result.overlap || result.iterations == gjk_max_iterations) break;
    const Vec2 direction = -closest.normalized();
    const SimplexVertex v = support_point(a, b, direction);
    ++result.iterations;
    if (record) record->push_back(GjkIteration{s, closest, direction, v});
    if (holds(unreduced.points.data(), unreduced.count, v) || no_progress(closest, v.w)) break;
    s.points[s.count++] = v;
  }
  result.point_a = combine(s, weights, &SimplexVertex::a);
  result.point_b = combine(s, weights, &SimplexVertex::b);
  if (!result.overlap) {
    const Vec2 w = combine(s, weights, &SimplexVertex::w);
    result.distance = w.norm();
    result.normal = w / result.distance;
  }
  return result;
}

// EPA from GJK's final simplex grown to a counter-clockwise triangle around the origin. Each
// iteration takes the polytope's edge nearest the origin, with outward normal m at distance d,
// and asks for s = s_D(m). If m · s − d is within the tolerance, or s is a point already in the
// polytope, that edge is D's own boundary nearest the origin: the depth is d. Otherwise s goes
// into the polytope between the edge's ends (and vertices it makes reflex leave).
EpaResult epa(const Convex& a, const Convex& b, const GjkResult& overlap,
              std::vector<EpaIteration>* record) {
  assert(overlap.overlap);
  Polytope p = first_polygon(a, b, overlap.simplex);
  if (p.count < 3) return flat_result(p);
  Edge edge = nearest_edge(p);
  int iterations = 0;
  while (iterations < epa_max_iterations) {
    const SimplexVertex s = support_point(a, b, edge.outward);
    ++iterations;
    if (record) record->push_back(epa_iteration(p, edge, s.w));
    const double gain = edge.outward.dot(s.w) - edge.distance;  // how far s is beyond the edge
    const bool converged = gain <= epa_progress * std::max(1.0, edge.distance);
    if (converged || holds(p.points.data(), p.count, s)) break;
    insert_after(p, edge.index, s);
    edge = nearest_edge(p);
  }
  return penetration(p, edge, iterations);
}

}  // namespace lamina
