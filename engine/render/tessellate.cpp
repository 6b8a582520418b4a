#include "render/tessellate.h"

#include <algorithm>
#include <cmath>

namespace lamina::render {
namespace {

constexpr double pi = 3.14159265358979323846;

Vec2 perpendicular(const Vec2& d) { return {-d.y(), d.x()}; }

// Offset of a polygon corner that moves both adjacent edges outward by `half` (a mitre).
Vec2 mitre(const Vec2& outward_before, const Vec2& outward_after, double half) {
  const Vec2 m = (outward_before + outward_after).normalized();
  return m * (half / std::max(m.dot(outward_before), 0.25));
}

// Unit outward normals of the edges i → i+1 of a convex polygon.
std::vector<Vec2> outward_normals(const std::vector<Vec2>& polygon) {
  Vec2 centroid = Vec2::Zero();
  for (const Vec2& p : polygon) centroid += p;
  centroid /= static_cast<double>(polygon.size());
  std::vector<Vec2> normals;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    Vec2 n = perpendicular(b - a).normalized();
    if (n.dot(0.5 * (a + b) - centroid) < 0.0) n = -n;
    normals.push_back(n);
  }
  return normals;
}

// Calls emit(a, b) for the dashes of the polyline: `dash` on, then 0.7 dash off.
template <typename Emit>
void for_each_dash(const std::vector<Vec2>& points, double dash, Emit emit) {
  const double period = 1.7 * dash;
  double phase = 0.0;  // distance along the pattern at the start of the current segment
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Vec2 a = points[i - 1], d = points[i] - a;
    const double length = d.norm();
    if (length <= 0.0) continue;
    for (double s = -phase; s < length; s += period) {
      const double start = std::max(s, 0.0), end = std::min(s + dash, length);
      if (end > start) emit(a + d * (start / length), a + d * (end / length));
    }
    phase = std::fmod(phase + length, period);
  }
}

}  // namespace

std::vector<Vec2> circle_points(const Vec2& centre, double radius) {
  // About one corner per 3 pixels of circumference: invisible facets, few triangles.
  const int count = std::clamp(static_cast<int>(std::ceil(2.0 * pi * radius / 3.0)), 12, 192);
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * pi * i / count;
    points.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
  }
  return points;
}

void fill_convex(Mesh& mesh, const std::vector<Vec2>& polygon, Colour colour) {
  for (std::size_t i = 2; i < polygon.size(); ++i) {
    mesh.triangle(polygon[0], polygon[i - 1], polygon[i], colour);
  }
}

void stroke_convex(Mesh& mesh, const std::vector<Vec2>& polygon, double width, Colour colour) {
  const std::vector<Vec2> normals = outward_normals(polygon);
  const std::size_t n = polygon.size();
  std::vector<Vec2> outer, inner;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 offset = mitre(normals[(i + n - 1) % n], normals[i], 0.5 * width);
    outer.push_back(polygon[i] + offset);
    inner.push_back(polygon[i] - offset);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    mesh.triangle(outer[i], outer[j], inner[j], colour);
    mesh.triangle(outer[i], inner[j], inner[i], colour);
  }
}

void stroke_segment(Mesh& mesh, const Vec2& a, const Vec2& b, double width, Colour colour) {
  const Vec2 d = b - a;
  if (d.norm() <= 0.0) return;
  const Vec2 side = perpendicular(d.normalized()) * (0.5 * width);
  mesh.triangle(a + side, b + side, b - side, colour);
  mesh.triangle(a + side, b - side, a - side, colour);
}

void stroke_polyline(Mesh& mesh, const std::vector<Vec2>& points, double width, Colour colour,
                     double dash) {
  if (dash > 0.0) {
    for_each_dash(points, dash,
                  [&](const Vec2& a, const Vec2& b) { stroke_segment(mesh, a, b, width, colour); });
    return;
  }
  for (std::size_t i = 1; i < points.size(); ++i) {
    stroke_segment(mesh, points[i - 1], points[i], width, colour);
    if (i + 1 < points.size()) fill_disc(mesh, points[i], 0.5 * width, colour);
  }
}

void fill_disc(Mesh& mesh, const Vec2& centre, double radius, Colour colour) {
  fill_convex(mesh, circle_points(centre, radius), colour);
}

void fill_ringed_disc(Mesh& mesh, const Vec2& centre, double radius, Colour fill, double ring_width,
                      Colour ring) {
  fill_disc(mesh, centre, radius + 0.5 * ring_width, ring);
  fill_disc(mesh, centre, radius - 0.5 * ring_width, fill);
}

ArrowShape arrow_shape(const Vec2& from, const Vec2& to, double width) {
  ArrowShape shape;
  const Vec2 d = to - from;
  const double length = d.norm();
  if (length < 1.0) return shape;
  const Vec2 u = d / length;
  const double head = std::min(4.5 * width, 0.45 * length);
  const Vec2 base = to - u * head;
  const Vec2 side = perpendicular(u) * (0.5 * head);
  shape.drawn = true;
  shape.shaft_from = from;
  shape.shaft_to = base + u * (0.1 * head);  // into the head, so no seam shows
  shape.head = {to, base + side, base - side};
  return shape;
}

std::vector<std::array<Vec2, 2>> dashes(const std::vector<Vec2>& points, double dash) {
  std::vector<std::array<Vec2, 2>> list;
  for_each_dash(points, dash, [&](const Vec2& a, const Vec2& b) { list.push_back({a, b}); });
  return list;
}

void draw_arrow(Mesh& mesh, const Vec2& from, const Vec2& to, double width, Colour colour) {
  const ArrowShape shape = arrow_shape(from, to, width);
  if (!shape.drawn) return;
  stroke_segment(mesh, shape.shaft_from, shape.shaft_to, width, colour);
  mesh.triangle(shape.head[0], shape.head[1], shape.head[2], colour);
}

}  // namespace lamina::render
