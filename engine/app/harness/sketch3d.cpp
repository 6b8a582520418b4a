#include "app/harness/sketch3d.h"

#include <algorithm>
#include <cmath>

#include "language/language.h"

namespace lamina::tutorial {

std::vector<Vec3> arc(const Vec3& centre, const Vec3& u, const Vec3& w, double radius,
                      double angle) {
  // One point every 3° at most, and at least 8 segments: smooth at any size on a slide.
  const int segments = std::max(8, static_cast<int>(std::ceil(std::abs(angle) / (M_PI / 60.0))));
  std::vector<Vec3> points;
  for (int i = 0; i <= segments; ++i) {
    const double phi = angle * i / segments;
    points.push_back(centre + radius * (std::cos(phi) * u + std::sin(phi) * w));
  }
  return points;
}

AngleMark angle_mark(const Vec3& centre, const Vec3& from, const Vec3& to, double radius,
                     double label_radius) {
  const Vec3 u = from.normalized();
  const Vec3 w = (to - to.dot(u) * u).normalized();  // the part of `to` across `from`
  const double angle = std::atan2(to.dot(w), to.dot(u));
  const Vec3 middle = std::cos(0.5 * angle) * u + std::sin(0.5 * angle) * w;
  return {arc(centre, u, w, radius, angle), centre + label_radius * middle};
}

void draw_world_axes(render::Frame& frame, const Vec3& origin, double length) {
  const render::Colour grey = render::palette::grey;
  const char* names[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    frame.arrows3.push_back({origin, origin + length * Vec3::Unit(i), grey, names[i]});
  }
  frame.legend.push_back(
      {render::LegendEntry::Sample::arrow, grey, fill(tr("world axes; {0}"), {frame.projection.description()})});
}

}  // namespace lamina::tutorial
