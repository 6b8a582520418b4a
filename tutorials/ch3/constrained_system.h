// Chapter 3's tutorial: a system of bodies and constraints stepped by constrained_step, shown
// one step at a time as the other chapters show theirs: step k goes from t = k Δt to t + Δt, a
// frame shows the bodies at t with what step k solved from them, and --explain prints it (every
// row's Jmap, Jsp, C, ζ, η, d, bounds, λ_exp, λ, W, the residual per sweep and, when small, the
// dense J, M⁻¹, J M⁻¹ Jᵀ).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "app/harness/format.h"
#include "app/harness/tutorial.h"
#include "constraints/constrained_step.h"

namespace lamina::ch3 {

using render::palette::blue;
using render::palette::bluish_green;
using render::palette::grey;
using render::palette::ink;
using render::palette::orange;
using render::palette::reddish_purple;
using render::palette::vermillion;
using tutorial::fixed;
using tutorial::scientific;

const Vec3 gravity = StepSettings().gravity;  // g, in m/s² (what constrained_step applies)

inline Vec2 planar(const Vec3& v) { return v.head<2>(); }
inline Vec3 spatial(const Vec2& v) { return Vec3(v.x(), v.y(), 0.0); }

// Bodies, their constraints and what the last constrained_step solved.
struct System {
  std::vector<RigidBody> bodies;  // now: at t + Δt once step k is taken
  ConstraintList constraints;
  ConstrainedStepSettings settings;
  WarmStart warm_start;
  std::vector<RigidBody> at_t;    // the bodies at t, where step k started (what a frame shows)
  StepReport report;              // what step k solved
  std::vector<double> C;          // each row's position error at t, in m (the report has ζ, not C)
  long step_index = -1;           // k, −1 before the first step

  // Takes step k + 1; `errors` are the rows' C now, kept for --explain.
  void step(std::vector<double> errors);
  // ‖W‖ after the last sweep of step k (eq. 3-23, 3-24).
  double last_residual() const;
};

// A fixed block just above a world pin, the ceiling it hangs from.
render::Body mount(const Vec3& pivot);

// Step k of the system: the bodies at t, each row named by `row_names` with its C, the solver's
// sweeps, the dense system when small, and the bodies at t + Δt with their F_c = Jᵀ λ.
tutorial::Explanation explain_system(const System& s, const std::string& title,
                                     const std::vector<std::string>& row_names);

// Step k of the system for the step-through viewer: the bodies at t and t + Δt, and each row
// (named by `row_names`, of kind "joint": chapter 3's constraints) with λ after every sweep.
void record_system(const System& s, const std::vector<std::string>& row_names,
                   tutorial::ViewerStep& step);

}  // namespace lamina::ch3
