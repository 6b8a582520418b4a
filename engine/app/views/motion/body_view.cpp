#include "app/views/motion/body_view.h"

#include "kinematics/momentum.h"

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

tutorial::ViewerBody viewer_body(const RigidBody& body, const Vec3& gravity) {
  tutorial::ViewerBody view;
  view.x = body.x.x();
  view.y = body.x.y();
  view.theta = planar_angle(body.q);
  view.vx = body.v.x();
  view.vy = body.v.y();
  view.omega = body.angular_velocity.z();
  view.fixed = body.is_static();
  if (!view.fixed) {
    view.energy = kinetic_energy(body.mass, body.v, body.inertia_world(), body.angular_velocity) -
                  body.mass * gravity.dot(body.x);
  }
  return view;
}

}  // namespace lamina::view
