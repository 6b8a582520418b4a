#include "render/oblique.h"

#include <cstdio>

namespace lamina::render {

Vec2 ObliqueProjection::project(const Vec3& p) const {
  const double dx = z_scale * std::cos(z_angle), dy = z_scale * std::sin(z_angle);
  return {p.x() + dx * p.z(), p.y() + dy * p.z()};
}

std::string ObliqueProjection::description() const {
  const char* name = z_scale == 0.5 ? "cabinet" : z_scale == 1.0 ? "cavalier" : "oblique";
  char text[96];
  std::snprintf(text, sizeof text, "%s projection: z drawn at %.0f°, × %g", name,
                z_angle * 180.0 / M_PI, z_scale);
  return text;
}

}  // namespace lamina::render
