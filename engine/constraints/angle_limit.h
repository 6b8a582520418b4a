// A one-sided joint-angle limit: the angle θ of body b relative to body a (or to the world),
// about z, may not pass a limit θ_L. An inequality row (chapter 3, "Inequality constraint").
//
//   θ = angle of q_a* q_b about z, in (−π, π]
//   lower limit  C = θ − θ_L ≥ 0,   s = +1         (eq. 3-17 with θ for (x − p)·N)
//   upper limit  C = θ_L − θ ≥ 0,   s = −1
//   Ċ = s (ω_b − ω_a) · ẑ
//   J = s [ 0ᵀ  −ẑᵀ   0ᵀ  ẑᵀ ]                       (jacobian_rows.h)
//   ζ = −C/Δt while C > 0, −β C/Δt once C ≤ 0       (eq. 3-18, 3-19, 3-14; constraint.h)
//   bounds [0, ∞): the limit only pushes away from itself, and only when J V(t+Δt) = ζ
//                  would otherwise fail (eq. 3-21, 3-22: λ ≥ 0, W ≥ 0, λ W = 0)
// The row is written every step, even far from the limit, where it asks only that the gap
// not close past zero within the step; its λ is then 0.
#pragma once

#include "constraints/constraint.h"

namespace lamina {

enum class LimitSide {
  lower,  // θ ≥ θ_L
  upper   // θ ≤ θ_L
};

class AngleLimit final : public Constraint {
 public:
  // Throws std::invalid_argument for a bad body pair or a limit outside (−π, π].
  AngleLimit(int body_a, int body_b, double limit, LimitSide side);

  // One inequality row, bounds [0, ∞).
  void write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                  std::vector<ConstraintRow>& rows) const override;
  const char* kind() const override { return "angle limit"; }
  std::array<int, 2> bodies() const override { return {body_a_, body_b_}; }

 private:
  int body_a_;     // the reference body, or world
  int body_b_;     // the body whose relative angle is limited
  double limit_;   // θ_L, in rad
  LimitSide side_; // whether θ_L is a lower or an upper limit
};

}  // namespace lamina
