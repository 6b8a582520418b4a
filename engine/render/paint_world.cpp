// Ground, paths, bodies, joints, arrows and labels: the scene itself, then its 3D items.
#include <algorithm>
#include <cmath>
#include <limits>

#include "render/paint.h"
#include "render/tessellate.h"

namespace lamina::render {
namespace {

// Unit vector at angle θ (world, y up).
Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }
// A world direction as a pixel direction (y flips).
Vec2 screen(const Vec2& world_direction) { return {world_direction.x(), -world_direction.y()}; }

std::vector<Vec2> box_corners(const Canvas& c, const Body& body) {
  const Vec2 ex = direction(body.angle) * body.half_extents.x();
  const Vec2 ey = direction(body.angle + M_PI / 2) * body.half_extents.y();
  return {c.px(body.centre + ex + ey), c.px(body.centre - ex + ey), c.px(body.centre - ex - ey),
          c.px(body.centre + ex - ey)};
}

// A body-frame point r at the body's pose, in pixels.
Vec2 body_px(const Canvas& c, const Body& body, const Vec2& r) {
  return c.px(body.centre + direction(body.angle) * r.x() + direction(body.angle + M_PI / 2) * r.y());
}

// A capsule's outline: the half circle round each cap, joined by the two straight sides.
std::vector<Vec2> capsule_points(const Canvas& c, const Body& body) {
  const int per_cap = 24;
  std::vector<Vec2> points;
  for (int cap = 0; cap < 2; ++cap) {
    const double side = cap == 0 ? 1.0 : -1.0;  // the +x cap first, then the −x one
    for (int k = 0; k <= per_cap; ++k) {
      const double a = -M_PI / 2 + M_PI * k / per_cap + (cap == 0 ? 0.0 : M_PI);
      points.push_back(body_px(c, body, Vec2(side * 0.5 * body.length, 0.0) +
                                            body.radius * direction(a)));
    }
  }
  return points;
}

// The outline of a body, in pixels, counter-clockwise in the world.
std::vector<Vec2> outline_of(const Canvas& c, const Body& body) {
  switch (body.shape) {
    case Body::Shape::box:
      return box_corners(c, body);
    case Body::Shape::circle:
      return circle_points(c.px(body.centre), body.radius * c.camera.pixels_per_metre());
    case Body::Shape::polygon: {
      std::vector<Vec2> points;
      for (const Vec2& v : body.vertices) points.push_back(body_px(c, body, v));
      return points;
    }
    case Body::Shape::capsule:
      return capsule_points(c, body);
  }
  return {};
}

// How far the body's outline lies from its centre along its own x axis, in m: where the
// rotation mark ends. A polygon's edge (a, b) with outward normal m is met at (m · a)/(m · x̂).
double reach_along_x(const Body& body) {
  switch (body.shape) {
    case Body::Shape::box:
      return body.half_extents.x();
    case Body::Shape::circle:
      return body.radius;
    case Body::Shape::capsule:
      return 0.5 * body.length + body.radius;
    case Body::Shape::polygon:
      break;
  }
  double reach = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < body.vertices.size(); ++i) {
    const Vec2& a = body.vertices[i];
    const Vec2 edge = body.vertices[(i + 1) % body.vertices.size()] - a;
    const Vec2 outward(edge.y(), -edge.x());
    if (outward.x() > 0.0) reach = std::min(reach, outward.dot(a) / outward.x());
  }
  return reach;
}

// The outline, filled, with a radius line from the centre that turns with the body (a fixed
// body never turns, so it has none).
void paint_body(Canvas& c, const Body& body) {
  const Vec2 centre = c.px(body.centre);
  const double reach = reach_along_x(body);
  const std::vector<Vec2> outline = outline_of(c, body);
  c.draw.fill_convex(outline, body.fill);
  c.draw.stroke_convex(outline, c.style.outline, palette::ink);
  Rect bounds{outline[0], outline[0]};
  for (const Vec2& p : outline) {
    bounds.min = bounds.min.cwiseMin(p);
    bounds.max = bounds.max.cwiseMax(p);
  }
  c.mark(LayoutBox::Kind::body, bounds);
  if (body.fixed) return;
  const Vec2 mark = c.px(body.centre + reach * direction(body.angle));
  c.draw.stroke_segment(centre, mark, c.style.line, palette::ink);
}

// A band below the surface line, hatched at 45°, as engineering drawings show fixed ground.
void paint_ground(Canvas& c, const Ground& ground) {
  const Vec2 normal = ground.normal.normalized();
  const Vec2 n = screen(normal), t(-n.y(), n.x());
  // The surface point nearest the middle of the frame; the line runs a frame diagonal each way.
  const Vec2 view_centre = c.camera.to_world(Vec2(c.size.width, c.size.height) / 2.0);
  const Vec2 foot = c.px(view_centre - (view_centre - ground.point).dot(normal) * normal);
  const double half = std::hypot(c.size.width, c.size.height);
  const double depth = 16.0 * c.style.unit, spacing = 14.0 * c.style.unit;
  const Vec2 a = foot - half * t, b = foot + half * t;
  c.draw.fill_convex({a, b, b - depth * n, a - depth * n}, tint(palette::grey, 0.18));
  for (double s = -half; s < half; s += spacing) {
    const Vec2 top = foot + s * t;
    c.draw.stroke_segment(top, top - depth * n + depth * t, c.style.unit, palette::grey);
  }
  c.draw.stroke_segment(a, b, c.style.outline * 1.25, palette::ink);
}

void paint_pin(Canvas& c, const Vec2& at) {
  c.draw.fill_ringed_disc(at, c.style.marker, palette::white, c.style.outline, palette::ink);
  c.draw.fill_disc(at, 0.3 * c.style.marker, palette::ink);
}

void paint_joint(Canvas& c, const Joint& joint) {
  c.draw.stroke_segment(c.px(joint.a), c.px(joint.b), c.style.outline, palette::ink);
  paint_pin(c, c.px(joint.a));
  paint_pin(c, c.px(joint.b));
}

void paint_arrow(Canvas& c, const Arrow& arrow) {
  if (arrow.layer && !c.overlays.has(*arrow.layer)) return;
  const Vec2 from = c.px(arrow.from), to = c.px(arrow.to);
  c.draw.draw_arrow(from, to, c.style.arrow, arrow.colour);
  if (arrow.label.empty()) return;
  const Vec2 d = (to - from).norm() > 0.0 ? Vec2((to - from).normalized()) : Vec2::UnitX();
  const TextStyle style{Typeface::sans, c.style.text_px, arrow.colour};
  c.write_label(arrow.label, style, to + d * (0.6 * c.style.text_px), d.x() < -0.3 ? 1.0 : 0.0);
}

void paint_label(Canvas& c, const Label& label) {
  const double align = label.align == Label::Align::left     ? 0.0
                       : label.align == Label::Align::centre ? 0.5
                                                             : 1.0;
  c.write_label(label.text, {Typeface::sans, c.style.text_px, label.colour}, c.px(label.at), align);
}

void paint_path(Canvas& c, const Path& path) {
  std::vector<Vec2> points;
  for (const Vec2& p : path.points) points.push_back(c.px(p));
  c.draw.stroke_polyline(points, c.style.line, path.colour,
                  path.dashed ? 9.0 * c.style.unit : 0.0);
}

// A marked point: a disc of its colour in an ink ring, its name to the right.
void paint_point(Canvas& c, const Point3& point, const ObliqueProjection& projection) {
  const Vec2 at = c.px(projection.project(point.at));
  draw_point(c, at, point.colour);
  if (point.label.empty()) return;
  c.write_label(point.label, {Typeface::sans, c.style.text_px, point.colour},
          at + Vec2(1.8 * c.style.marker, 0.0));
}

// The 3D items, each projected onto the plane and drawn as its planar counterpart.
void paint_3d(Canvas& c, const Frame& frame) {
  const ObliqueProjection& p = frame.projection;
  for (const Path3& path : frame.paths3) {
    Path flat{{}, path.colour, path.dashed};
    for (const Vec3& point : path.points) flat.points.push_back(p.project(point));
    paint_path(c, flat);
  }
  for (const Arrow3& a : frame.arrows3) {
    paint_arrow(c, {p.project(a.from), p.project(a.to), a.colour, a.label, std::nullopt});
  }
  for (const Point3& point : frame.points3) paint_point(c, point, p);
  for (const Label3& l : frame.labels3) {
    paint_label(c, {p.project(l.at), l.text, l.colour, l.align});
  }
}

}  // namespace

void paint_world(const Frame& frame, Canvas& canvas) {
  for (const Ground& g : frame.grounds) paint_ground(canvas, g);
  for (const Path& p : frame.paths) paint_path(canvas, p);
  for (const Body& b : frame.bodies) paint_body(canvas, b);
  for (const Joint& j : frame.joints) paint_joint(canvas, j);
  for (const Arrow& a : frame.arrows) paint_arrow(canvas, a);
  for (const Label& l : frame.labels) paint_label(canvas, l);
  paint_3d(canvas, frame);
}

}  // namespace lamina::render
