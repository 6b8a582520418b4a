#include "ch5/corner_inset.h"

#include <algorithm>

namespace lamina::ch5 {
namespace {

// A segment clipped to the square |p − centre|∞ ≤ half (Liang–Barsky); false when outside.
bool clip(Vec2& a, Vec2& b, const Vec2& centre, double half) {
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    for (double side : {-1.0, 1.0}) {
      const double p = side * d[axis], q = half - side * (a[axis] - centre[axis]);
      if (p == 0.0) {
        if (q < 0.0) return false;
        continue;
      }
      const double t = q / p;
      if (p < 0.0) t0 = std::max(t0, t);
      if (p > 0.0) t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return false;
  const Vec2 start = a;
  a = start + t0 * d;
  b = start + t1 * d;
  return true;
}

}  // namespace

void draw_inset(render::Frame& frame, const Inset& inset, const RigidBody& box, const Vec3& corner,
                const Vec3* contact) {
  const Vec3 at_corner = box.x + box.rotation * corner;
  const Vec2 focus(at_corner.x(), 0.0);  // the ground's surface under the corner
  const Vec2& centre = inset.centre;
  auto map = [&](const Vec3& p) { return Vec2(centre + inset.magnify * (p.head<2>() - focus)); };
  auto segment = [&](Vec2 a, Vec2 b, render::Colour colour) {
    if (clip(a, b, centre, inset.half)) frame.paths.push_back({{a, b}, colour, false});
  };
  const Vec2 h(inset.half, inset.half), k(inset.half, -inset.half);
  frame.paths.push_back(
      {{centre - h, centre - k, centre + h, centre + k, centre - h}, render::palette::grey, false});
  segment(map(Vec3(focus.x() - 1.0, 0.0, 0.0)), map(Vec3(focus.x() + 1.0, 0.0, 0.0)),
          render::palette::ink);
  for (int i = -4; i <= 4; ++i) {  // the ground's hatching
    const Vec2 top = centre + Vec2(0.15 * i, 0.0);
    segment(top, top + Vec2(-0.4, -0.4), render::palette::grid);
  }
  for (int i = 0; i < 4; ++i) {  // the box's outline, corner to corner
    const Vec3 r0(i == 0 || i == 3 ? -0.5 : 0.5, i < 2 ? -0.5 : 0.5, 0.0);
    const Vec3 r1(i == 0 || i == 1 ? 0.5 : -0.5, i == 0 || i == 3 ? -0.5 : 0.5, 0.0);
    segment(map(box.x + box.rotation * r0), map(box.x + box.rotation * r1), render::palette::blue);
  }
  if (contact != nullptr) {
    const Vec2 at = map(*contact);
    frame.paths.push_back(
        {{at + Vec2(-0.03, 0.0), at + Vec2(0.03, 0.0)}, render::palette::vermillion, false});
    frame.paths.push_back(
        {{at + Vec2(0.0, -0.03), at + Vec2(0.0, 0.03)}, render::palette::vermillion, false});
  }
  frame.labels.push_back({centre + Vec2(0.0, inset.half + 0.08), inset.title, render::palette::ink,
                          render::Label::Align::centre});
  for (int line = 0; line < 2; ++line) {
    frame.labels.push_back({centre - Vec2(0.0, inset.half + 0.08 + 0.1 * line), inset.lines[line],
                            render::palette::ink, render::Label::Align::centre});
  }
}

}  // namespace lamina::ch5
