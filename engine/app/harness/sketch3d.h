// What the figures of space draw with (render::Frame's 3D items): arcs and circles in a plane of
// space, angle marks, and the world axes that show how the frame's oblique projection draws x, y
// and z. Plain geometry: the physics is the tutorials'.
#pragma once

#include <vector>

#include "kinematics/math_types.h"
#include "render/frame.h"

namespace lamina::tutorial {

// Points of the arc of `radius` about `centre` in the plane of the orthonormal u, w, from the
// direction u (angle 0) to the direction cos(angle) u + sin(angle) w; a full circle at 2π.
std::vector<Vec3> arc(const Vec3& centre, const Vec3& u, const Vec3& w, double radius,
                      double angle);

// The mark of the angle (at most π) between the directions `from` and `to`, neither parallel to
// the other, at `centre`.
struct AngleMark {
  std::vector<Vec3> points;  // the arc of `radius` from `from` to `to`, in m
  Vec3 label_at;             // its middle direction at `label_radius`: where the angle's name goes
};
AngleMark angle_mark(const Vec3& centre, const Vec3& from, const Vec3& to, double radius,
                     double label_radius);

// Grey x, y and z arrows of `length` from `origin`, named at their tips, and a legend row that
// states the frame's projection.
void draw_world_axes(render::Frame& frame, const Vec3& origin, double length);

}  // namespace lamina::tutorial
