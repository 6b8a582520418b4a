#include "render/oblique.h"

#include <cstdio>

#include "language/language.h"

namespace lamina::render {

Vec2 ObliqueProjection::project(const Vec3& p) const {
  const double dx = z_scale * std::cos(z_angle), dy = z_scale * std::sin(z_angle);
  return {p.x() + dx * p.z(), p.y() + dy * p.z()};
}

std::string ObliqueProjection::description() const {
  char angle[16], scale[32];
  std::snprintf(angle, sizeof angle, "%.0f", z_angle * 180.0 / M_PI);
  std::snprintf(scale, sizeof scale, "%g", z_scale);
  const char* pattern = z_scale == 0.5   ? tr("cabinet projection: z drawn at {0}°, × {1}")
                        : z_scale == 1.0 ? tr("cavalier projection: z drawn at {0}°, × {1}")
                                         : tr("oblique projection: z drawn at {0}°, × {1}");
  return fill(pattern, {angle, scale});
}

}  // namespace lamina::render
