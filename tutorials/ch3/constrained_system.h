// Chapter 3's tutorial: a system of bodies and constraints stepped by constrained_step, what
// its last step solved, and --explain for it in the text's terms (every row's Jmap, Jsp, C, ζ,
// η, d, bounds, λ_exp, λ, W, the residual per sweep and, when small, the dense J, M⁻¹, J M⁻¹ Jᵀ).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "constraints/constrained_step.h"
#include "harness/format.h"
#include "harness/tutorial.h"

namespace lamina::ch3 {

using Vec2 = render::Vec2;
using render::palette::blue;
using render::palette::bluish_green;
using render::palette::grey;
using render::palette::ink;
using render::palette::orange;
using render::palette::reddish_purple;
using render::palette::vermillion;
using tutorial::fixed;
using tutorial::scientific;

const Vec3 gravity(0.0, -9.8, 0.0);  // g, in m/s²

inline Vec2 planar(const Vec3& v) { return v.head<2>(); }
inline Vec3 spatial(const Vec2& v) { return Vec3(v.x(), v.y(), 0.0); }

// Bodies, their constraints and what the last constrained_step solved.
struct System {
  std::vector<RigidBody> bodies;
  ConstraintList constraints;
  ConstrainedStepSettings settings;
  WarmStart warm_start;
  StepReport report;      // the last step's; empty before the first
  std::vector<double> C;  // each row's position error at the start of the last step, in m
  bool stepped = false;

  // One step; `errors` are the rows' C now, kept for --explain (the report has ζ, not C).
  void step(std::vector<double> errors) {
    C = std::move(errors);
    constrained_step(bodies, constraints, settings, warm_start, &report);
    stepped = true;
  }
  // F_c = Jᵀ λ on body b from the last step's rows (eq. 3-11), [F τ].
  Vec6 constraint_force(int b) const;
  // ‖W‖ after the last sweep of the last step (eq. 3-23, 3-24); 0 before the first step.
  double last_residual() const;
};

// A fixed block just above a world pin, the ceiling it hangs from.
render::Body mount(const Vec3& pivot);

// The bodies after the step, the solver's sweeps and each row, named by `row_names`.
tutorial::Explanation explain_system(const System& s, const std::string& title,
                                     const std::vector<std::string>& row_names);

}  // namespace lamina::ch3
