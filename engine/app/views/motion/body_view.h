// How a rigid body looks in a frame: a box at the body's pose (planar: x–y position, angle about
// z), with its velocity for the velocities overlay and no mark of its own rotation when fixed.
#pragma once

#include "motion/rigid_body.h"
#include "render/frame.h"

namespace lamina::view {

// A box of the given half extents at the body's pose.
render::Body box_view(const RigidBody& body, const Vec2& half_extents, render::Colour fill);

}  // namespace lamina::view
