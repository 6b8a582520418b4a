// How a rigid body looks in a frame: a box at the body's pose (planar: x–y position, angle about
// z), with its velocity for the velocities overlay and no mark of its own rotation when fixed.
#pragma once

#include "app/harness/viewer.h"
#include "motion/rigid_body.h"
#include "render/frame.h"

namespace lamina::view {

// A box of the given half extents at the body's pose.
render::Body box_view(const RigidBody& body, const Vec2& half_extents, render::Colour fill);

// The body's planar state for the step-through viewer, with its energy under gravity g:
// E = ½ m v·v + ½ ω·I ω − m g·x (eq. 1-47 and the potential of F_ext = m g, eq. 5-2).
tutorial::ViewerBody viewer_body(const RigidBody& body, const Vec3& gravity);

}  // namespace lamina::view
