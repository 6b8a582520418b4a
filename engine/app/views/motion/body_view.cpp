#include "app/views/motion/body_view.h"

namespace lamina::view {

render::Body box_view(const RigidBody& body, const Vec2& half_extents, render::Colour fill) {
  render::Body view;
  view.shape = render::Body::Shape::box;
  view.centre = body.x.head<2>();
  view.angle = planar_angle(body.q);
  view.half_extents = half_extents;
  view.fill = fill;
  view.velocity = body.v.head<2>();
  view.fixed = body.is_static();
  return view;
}

}  // namespace lamina::view
