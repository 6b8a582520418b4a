// What one World step computed, in the text's terms and in World::step's order (chapter 5):
//   the bodies at t (V, M⁻¹, F_ext: eq. 3-5, 5-1, 5-2), the contacts found and kept
//   (Fig 4-2..4-5, eq. 4-1, 5-12) and the joints, each row of the velocity MLCP assembled from
//   them (J, ζ, η, d, bounds, λ_exp, λ, W: eq. 3-8..3-26), the PGS sweeps, the split-impulse
//   position solve (beyond the text), the constraint forces F_c = Jᵀ λ (eq. 3-11, 5-9) and the
//   bodies at t + Δt (eq. 2-3..2-6), then the dense system when it is small.
// `lamina run --explain K` and every tutorial's --explain K print this for step K.
#pragma once

#include <string>
#include <vector>

#include "app/views/constraints/mlcp_explanation.h"
#include "contact/world.h"

namespace lamina::view {

// `world` has just taken the step `report` records; `names` names its bodies, in order.
// `each_row`: a section per row of the MLCP (the viewer shows them as a table instead).
Explanation explain_world_step(const World& world, const WorldReport& report,
                               const std::vector<std::string>& names, bool each_row = true);

// The same step for the step-through viewer: its explanation as phases, the bodies at t and
// t + Δt, every row with its kind, contact or joint and λ after each sweep, the contacts (with
// their origin, Fig 4-2..4-5) and the joints.
tutorial::ViewerStep viewer_step(const World& world, const WorldReport& report,
                                 const std::vector<std::string>& names);

}  // namespace lamina::view
