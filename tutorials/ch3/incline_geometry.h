// The incline of Fig 3-1 and Fig 3-2: a 30° slope, a 2 kg box, and the line through p with
// normal N that the box's centre is held on (Fig 3-1) or kept above (Fig 3-2).
#pragma once

#include <cmath>

#include "motion/rigid_body.h"
#include "render/frame.h"

namespace lamina::ch3::incline {

constexpr double angle = M_PI / 6.0;                            // θ, 30°
inline const Vec2 box_half(0.4, 0.25);                          // box half extents, in m
constexpr double box_density = 5.0;                             // kg/m²: m = 2 kg
inline const Vec2 slope_top(0.0, 3.6);                          // a point of the surface, in m
inline const Vec2 downhill(std::cos(angle), -std::sin(angle));  // unit, along the slope
inline const Vec2 normal(std::sin(angle), std::cos(angle));     // N

// p: the point of the line the centre is held on, half a box above the surface, in m.
Vec3 line_point();
// The box turned with the slope, its centre on the line `along` m down the slope from p.
RigidBody box_on_line(double along);
// C = (x − p)·N of a box (eq. 3-1, 3-13), in m.
double error(const RigidBody& box);
// The surface, the line C = 0 dashed `length` m down the slope from p, and p and N on it.
void draw_line(render::Frame& frame, double length);
// The box as a frame draws it.
render::Body box_view(const RigidBody& box);

}  // namespace lamina::ch3::incline
