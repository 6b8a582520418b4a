// A magnified view of one corner of the walk-through's box where it meets the ground, for the
// chapter-5 frames: the ground's surface, the box's outline near the corner, the contact point
// when there is one, and two lines of text below it.
#pragma once

#include <string>

#include "motion/rigid_body.h"
#include "render/frame.h"

namespace lamina::ch5 {

struct Inset {
  Vec2 centre;                 // where the inset sits in the frame, in m of the frame
  double half = 0.3;           // half its side, in m of the frame
  double magnify = 20.0;       // how much larger than the frame it draws
  std::string title;           // above it, e.g. "corner a ×20"
  std::string lines[2];        // below it, e.g. "ε = −0.0100 m", "fresh: the deepest point"
};

// Draws `inset` around the ground point below the box corner at body-frame offset `corner`
// (half extents 0.5), with the contact point `contact` marked when it has one.
void draw_inset(render::Frame& frame, const Inset& inset, const RigidBody& box, const Vec3& corner,
                const Vec3* contact);

}  // namespace lamina::ch5
