// How a frame draws 3D items: an oblique parallel projection onto the x–y plane of the scene.
//
// x and y are drawn as they are; z is drawn along one fixed direction of the plane, at angle
// `z_angle` from +x (counter-clockwise, y up), shortened by `z_scale`:
//   (x, y, z) → (x + z_scale cos(z_angle) z,  y + z_scale sin(z_angle) z).
// Cabinet projection halves z (z_scale = ½), cavalier keeps it (z_scale = 1). The default is
// cabinet with +z, which points at the viewer in a right-handed x–y–z, drawn down and to the left
// (225°). A planar item (z = 0) lands where the 2D items put it.
#pragma once

#include <cmath>
#include <string>

#include "kinematics/math_types.h"

namespace lamina::render {

struct ObliqueProjection {
  double z_angle = 1.25 * M_PI;  // direction along which +z is drawn, from +x, in rad
  double z_scale = 0.5;          // m drawn per m of z

  // The point of the x–y plane, in m, where the 3D point p, in m, is drawn.
  Vec2 project(const Vec3& p) const;
  // The projection in words, for a legend or a panel:
  // "cabinet projection: z drawn at 225°, × 0.5".
  std::string description() const;
};

}  // namespace lamina::render
