// A solved MLCP explained in the text's terms (chapter 3): what each row asked and got, how the
// sweeps went, and for a small system the dense matrices. Every number is read from the one
// assembled MLCP (constraints/mlcp.h) and the λ its solve produced (constraints/step_report.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/harness/explanation.h"
#include "app/harness/viewer.h"
#include "constraints/step_report.h"
#include "motion/rigid_body.h"

namespace lamina::view {

using tutorial::Explanation;
using tutorial::Quantity;
using tutorial::Section;

// Row i: its bodies (Jmap), J blocks (eq. 3-8), ζ (3-15), η and d (3-16), the bounds as solved
// (3-24, 3-26), λ_exp, λ (3-24) and W (3-23). `bodies` names the bodies by index.
Section row_section(const StepReport& report, int i, const std::string& title,
                    const std::vector<std::string>& bodies);

// The sweeps run and the residual ‖W‖ after each (eq. 3-23, 3-24).
Section sweeps_section(const StepReport& report, const std::string& title);

// J (s × 6n), M⁻¹ and J M⁻¹ Jᵀ (eq. 3-8, 3-12, 3-16) written out, when they fit a terminal
// (J and M⁻¹ for n ≤ 2 bodies, J M⁻¹ Jᵀ for s ≤ 8 rows); nothing for a larger system.
std::optional<Section> dense_section(const StepReport& report, const std::vector<RigidBody>& bodies,
                                     const std::string& title);

// A body's state: x, θ, v, ω with the equation numbers `tags` gives them (e.g. {"3-5", ...} at
// t, {"2-5", "2-6", "2-3", "2-4"} after the step).
struct StateTags {
  std::string x, theta, v, omega;
};
Section body_section(const std::string& title, const RigidBody& body, const StateTags& tags);

// Body b's constraint force F_c = Jᵀ λ, [f_c; τ_c] (eq. 3-11, 5-9).
Quantity constraint_force(const StepReport& report, int body);

// The rows of the solved MLCP for the step-through viewer, titled by `titles` (one per row; the
// kind is "friction" for a row bounded by ±μ λc, "row" otherwise, for the caller to refine),
// with λ after each recorded sweep and the residuals after each.
void add_viewer_rows(const StepReport& report, const std::vector<std::string>& titles,
                     tutorial::ViewerStep& step);

// The names of n bodies when they have none of their own: "body 0", "body 1", ...
std::vector<std::string> numbered_bodies(std::size_t count);

}  // namespace lamina::view
