#include "ch3/incline_geometry.h"

#include "app/views/motion/body_view.h"

namespace lamina::ch3::incline {

Vec3 line_point() {
  const Vec2 p = slope_top + box_half.y() * normal;
  return Vec3(p.x(), p.y(), 0.0);
}

RigidBody box_on_line(double along) {
  const Vec3 centre = line_point() + along * Vec3(downhill.x(), downhill.y(), 0.0);
  return box_body(box_density, box_half.x(), box_half.y(), centre, -angle);
}

double error(const RigidBody& box) { return (box.x - line_point()).head<2>().dot(normal); }

void draw_line(render::Frame& frame, double length) {
  frame.grounds.push_back({slope_top, normal});
  const Vec2 p = line_point().head<2>();
  frame.paths.push_back({{p - 0.5 * downhill, p + length * downhill}, render::palette::grey, true});
  frame.arrows.push_back({p, p + 0.6 * normal, render::palette::ink, "N", std::nullopt});
  frame.labels.push_back({p - Vec2(0.12, 0.05), "p", render::palette::ink, render::Label::Align::right});
}

render::Body box_view(const RigidBody& box) {
  return view::box_view(box, box_half, tint(render::palette::sky_blue, 0.35));
}

}  // namespace lamina::ch3::incline
