#include "ch4/pair_figure.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "app/harness/format.h"
#include "app/views/contact/world_view.h"
#include "kinematics/mass_properties.h"
#include "kinematics/rotation.h"

namespace lamina::ch4 {
namespace {

namespace palette = render::palette;
using Align = render::Label::Align;
using tutorial::fixed;

// A and B as body 1 and body 2 of the other chapter-4 frames.
const render::Colour a_fill = palette::grid;
const render::Colour b_fill = tint(palette::sky_blue, 0.35);

// The pair: A a hexagon, B a triangle, counter-clockwise in their body frames, in m (centred()
// moves each to be about its centroid, the form Shape::polygon takes).
const std::vector<Vec2> hexagon{{1.0, -0.3},  {1.1, 0.45}, {0.35, 1.0},
                                {-0.6, 0.85}, {-1.0, 0.0}, {-0.3, -0.75}};
const std::vector<Vec2> triangle{{0.6, -0.55}, {0.25, 0.75}, {-0.85, -0.2}};
const Vec2 a_centre(-3.2, 0.6);  // A's centroid, in m
constexpr double a_angle = 0.3;  // A's angle, in rad
constexpr double b_angle = 0.9;  // B's angle, in rad

constexpr double name_offset = 0.25;  // a vertex's name this far out from it, in m

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

// The polygon of `vertices` moved to be about its centroid c (mass_properties.h): v − c.
Shape centred(std::vector<Vec2> vertices) {
  const Vec2 c = polygon_moments(vertices).centroid;
  for (Vec2& v : vertices) v -= c;
  return Shape::polygon(vertices);
}

Pose2 placed(const Vec2& x, double angle) {
  return Pose2{x, rotation_z(angle).topLeftCorner<2, 2>()};
}

// The convex hull, counter-clockwise (Andrew's monotone chain: the lower chain left to right,
// then the upper chain back, each dropping points that do not turn left).
std::vector<Vec2> hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](const Vec2& p, const Vec2& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  const int n = static_cast<int>(points.size());
  std::vector<Vec2> h(2 * points.size());
  int k = 0;
  for (int i = 0; i < n; ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], points[i] - h[k - 2]) <= 0.0) --k;
    h[k++] = points[i];
  }
  for (int i = n - 2, lower = k + 1; i >= 0; --i) {
    while (k >= lower && cross(h[k - 1] - h[k - 2], points[i] - h[k - 2]) <= 0.0) --k;
    h[k++] = points[i];
  }
  h.resize(static_cast<std::size_t>(k - 1));
  return h;
}

}  // namespace

std::string vertex_name(char body, int index) {
  std::string name(1, body);
  for (const char digit : std::to_string(index)) {
    name += std::string("\xE2\x82") + static_cast<char>(0x80 + (digit - '0'));  // U+2080 + digit
  }
  return name;
}

std::string point_name(const SimplexVertex& v) {
  return vertex_name('b', v.index_b) + "−" + vertex_name('a', v.index_a);
}

std::string planar(const Vec2& v) { return "(" + fixed(v.x()) + ", " + fixed(v.y()) + ")"; }
tutorial::Json json_of(const Vec2& v) { return {v.x(), v.y()}; }
tutorial::Json rows_of(const std::vector<Vec2>& points) {
  tutorial::Json rows = tutorial::Json::array();
  for (const Vec2& p : points) rows.push_back(json_of(p));
  return rows;
}

SeparatingAxis least_overlap(const Convex& a, const Convex& b) {
  const auto extent = [](const Convex& c, const Vec2& m) {
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < c.count; ++i) {
      lo = std::min(lo, m.dot(c.vertices[i]));
      hi = std::max(hi, m.dot(c.vertices[i]));
    }
    return std::array<double, 2>{lo, hi};
  };
  SeparatingAxis best;
  for (const auto& [c, body] : {std::pair{&a, 'a'}, std::pair{&b, 'b'}}) {
    for (int i = 0; i < c->count; ++i) {
      const int next = (i + 1) % c->count;
      const Vec2 e = c->vertices[next] - c->vertices[i];
      const Vec2 m = Vec2(e.y(), -e.x()).normalized();  // counter-clockwise: outward is right
      const auto [lo_a, hi_a] = extent(a, m);
      const auto [lo_b, hi_b] = extent(b, m);
      const double overlap = std::min(hi_a, hi_b) - std::max(lo_a, lo_b);
      if (overlap < best.overlap)
        best = {overlap, m, vertex_name(body, i) + vertex_name(body, next)};
    }
  }
  return best;
}

PairFigure::PairFigure(const Vec2& b_centre, const Vec2& origin, double name_side)
    : shapes_{centred(hexagon), centred(triangle)},
      poses_{placed(a_centre, a_angle), placed(b_centre, b_angle)},
      cores_{core_of(shapes_[0], poses_[0]), core_of(shapes_[1], poses_[1])},
      origin_(origin),
      name_side_(name_side) {
  std::vector<Vec2> points;
  for (int i = 0; i < a().count; ++i) {
    for (int j = 0; j < b().count; ++j) {
      differences_.push_back(
          {a().vertices[i], b().vertices[j], b().vertices[j] - a().vertices[i], i, j});
      points.push_back(differences_.back().w);
    }
  }
  difference_ = hull(points);
}

const SimplexVertex& PairFigure::source(const Vec2& w) const {
  return *std::min_element(differences_.begin(), differences_.end(),
                           [&](const SimplexVertex& p, const SimplexVertex& q) {
                             return (p.w - w).squaredNorm() < (q.w - w).squaredNorm();
                           });
}

void PairFigure::draw_shapes(render::Frame& frame, const SimplexVertex* marked, bool names) const {
  for (int k = 0; k < 2; ++k) {
    render::Body body;
    view::set_outline(body, shape(k));
    body.centre = pose(k).x;
    body.angle = std::atan2(pose(k).R(1, 0), pose(k).R(0, 0));
    body.fill = k == 0 ? a_fill : b_fill;
    body.fixed = true;  // no centre mark: nothing moves here
    frame.bodies.push_back(body);
    frame.labels.push_back({pose(k).x, k == 0 ? "A" : "B", palette::ink, Align::centre});
    const Convex& core = cores_[static_cast<std::size_t>(k)];
    for (int i = 0; names && i < core.count; ++i) {
      const bool hit = marked && (k == 0 ? marked->index_a : marked->index_b) == i;
      const Vec2 out = (core.vertices[i] - pose(k).x).normalized();
      frame.labels.push_back({core.vertices[i] + name_offset * out,
                              vertex_name(k == 0 ? 'a' : 'b', i), hit ? added : palette::grey,
                              Align::centre});
    }
  }
  if (marked) frame.arrows.push_back({marked->a, marked->b, added, "", std::nullopt});
}

void PairFigure::draw_difference(render::Frame& frame) const {
  render::Body body;
  body.shape = render::Body::Shape::polygon;
  body.centre = origin_;
  body.vertices = difference_;
  body.fill = d_fill;
  body.fixed = true;
  frame.bodies.push_back(body);
  const Vec2 top = *std::max_element(difference_.begin(), difference_.end(),
                                     [](const Vec2& p, const Vec2& q) { return p.y() < q.y(); });
  frame.labels.push_back(
      {at(top) + Vec2(0.0, -0.35), "D = B − A", palette::bluish_green, Align::centre});
  frame.labels.push_back({origin_ + Vec2(0.12 * name_side_, 0.0), "O", palette::ink,
                          name_side_ < 0.0 ? Align::right : Align::left});
  frame.points3.push_back({lift(origin_), palette::ink, ""});
}

void PairFigure::stroke(render::Frame& frame, const std::vector<Vec2>& w, render::Colour colour,
                        bool closed, bool dashed) const {
  render::Path3 path{{}, colour, dashed};
  for (const Vec2& p : w) path.points.push_back(lift(at(p)));
  if (closed && w.size() > 2) path.points.push_back(lift(at(w.front())));
  frame.paths3.push_back(path);
}

void PairFigure::mark(render::Frame& frame, const Vec2& w, render::Colour colour,
                      const std::string& name) const {
  frame.points3.push_back({lift(at(w)), colour, name});
}

std::vector<Vec2> points_of(const Simplex& s) {
  std::vector<Vec2> w;
  for (int i = 0; i < s.count; ++i) w.push_back(s.points[i].w);
  return w;
}

std::string names_of(const Simplex& s) {
  std::string names;
  for (int i = 0; i < s.count; ++i) names += (i ? ", " : "") + point_name(s.points[i]);
  return names;
}

void draw_simplex(render::Frame& frame, const PairFigure& figure, const Simplex& s) {
  figure.stroke(frame, points_of(s), kept, true, false);
  for (int i = 0; i < s.count; ++i)
    figure.mark(frame, s.points[i].w, kept, point_name(s.points[i]));
}

render::Panel panel(const std::string& title, std::vector<std::string> lines) {
  return {render::Corner::bottom_left, title, palette::ink, std::move(lines)};
}

}  // namespace lamina::ch4
