// How a constraint with ends looks in a frame: a link between its two anchors with a pin at
// each end (engine/render/frame.h), at the bodies' state.
#pragma once

#include <optional>
#include <vector>

#include "constraints/constraint.h"
#include "render/frame.h"

namespace lamina::view {

// The constraint between its ends (a rod, a pin); nothing for one without ends (an angle limit,
// an incline).
std::optional<render::Joint> joint_view(const std::vector<RigidBody>& bodies,
                                        const Constraint& joint);

}  // namespace lamina::view
