// How a World looks in a frame (engine/render/frame.h): its bodies, the contacts a step solved
// with their forces, and its joints. A frame shows the state at the start of a step, t, with
// what that step solved from it (the text's walk-through reads the same way: "at t = τ the MLCP
// gives λ1").
#pragma once

#include <optional>
#include <vector>

#include "app/views/constraints/constraint_view.h"
#include "contact/world.h"
#include "render/frame.h"

namespace lamina::view {

// A body drawn with its shape at its state.
render::Body body_view(const RigidBody& body, const Shape& shape, render::Colour fill);
// Gives a drawn body the outline of `shape` (its kind, sizes and a polygon's vertices).
void set_outline(render::Body& view, const Shape& shape);

// A contact as drawn: point, normal, λ of its contact row along n and of its friction row along
// u1 = z × n (chapter 4: the force on body 2 is λ_n n + λ_t u1), fresh or cached.
render::Contact contact_view(const ContactInfo& contact);

// The world at the start of its last step: the bodies at t (`at_t`, as that step found them;
// static ones grey), the contacts the step solved and the joints at t. Caption and status are
// left to the caller.
render::Frame world_frame(const World& world, const std::vector<RigidBody>& at_t);

}  // namespace lamina::view
