// How a chapter-2+ rigid body looks in a frame (for tutorials that link lamina::motion).
// Header-only, so the harness itself links no physics stage past chapter 1.
#pragma once

#include "motion/rigid_body.h"
#include "render/frame.h"

namespace lamina::tutorial {

// A box of the given half extents at the body's pose (planar: x–y position, angle about z).
inline render::Body box_view(const RigidBody& body, const render::Vec2& half_extents,
                             render::Colour fill) {
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

}  // namespace lamina::tutorial
