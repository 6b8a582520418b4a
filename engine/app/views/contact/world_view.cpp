#include "app/views/contact/world_view.h"

#include "app/views/motion/body_view.h"

namespace lamina::view {
namespace {

constexpr render::Colour fixed_fill = render::tint(render::palette::grey, 0.3);

}  // namespace

render::Body body_view(const RigidBody& body, const Shape& shape, render::Colour fill) {
  render::Body view = box_view(body, shape.half_extents, fill);
  set_outline(view, shape);
  return view;
}

void set_outline(render::Body& view, const Shape& shape) {
  view.shape = render::Body::Shape::box;
  view.half_extents = shape.half_extents;
  view.radius = shape.radius;
  switch (shape.kind) {
    case Shape::Kind::box:
      break;
    case Shape::Kind::circle:
      view.shape = render::Body::Shape::circle;
      break;
    case Shape::Kind::polygon:
      view.shape = render::Body::Shape::polygon;
      view.vertices.assign(shape.vertices.begin(), shape.vertices.begin() + shape.vertex_count);
      break;
    case Shape::Kind::capsule:
      view.shape = render::Body::Shape::capsule;
      view.length = shape.length;
      break;
  }
}

render::Contact contact_view(const ContactInfo& c) {
  render::Contact view;
  view.point = c.point.head<2>();
  view.normal = c.normal.head<2>();
  view.tangent = Vec2(-c.normal.y(), c.normal.x());
  view.normal_force = c.lambda_normal;
  view.friction_force = c.lambda_tangent;
  view.origin = c.origin == ContactOrigin::kept      ? render::Contact::Origin::kept
                : c.origin == ContactOrigin::refound ? render::Contact::Origin::refound
                                                     : render::Contact::Origin::fresh;
  return view;
}

render::Frame world_frame(const World& world, const std::vector<RigidBody>& at_t) {
  render::Frame frame;
  for (std::size_t i = 0; i < at_t.size(); ++i) {
    const RigidBody& body = at_t[i];
    frame.bodies.push_back(body_view(body, world.shape(static_cast<int>(i)),
                                     body.is_static() ? fixed_fill : render::Body().fill));
  }
  for (const ContactInfo& c : world.contacts()) frame.contacts.push_back(contact_view(c));
  for (int j = 0; j < world.joint_count(); ++j) {
    if (auto joint = joint_view(at_t, world.joint(j))) frame.joints.push_back(*joint);
  }
  return frame;
}

}  // namespace lamina::view
