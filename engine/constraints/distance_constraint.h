// A distance constraint: a rigid rod (pendulum, rope segment) of length L between two anchors,
// on two bodies or on a body and the world (chapter 3, "Inequality constraint": an equality).
//
//   d = p_b − p_a,   u = d / |d|
//   C = |d| − L                                    = 0
//   Ċ = u · (ṗ_b − ṗ_a)
//   J = [ −uᵀ  −(r_a × u)ᵀ   uᵀ  (r_b × u)ᵀ ]     (jacobian_rows.h)
//   ζ = −β C / Δt                                  (eq. 3-14, see constraint.h)
//   bounds (−∞, ∞): the rod pushes and pulls (a rope that only pulls would be [0, ∞) on −C)
#pragma once

#include "constraints/constraint.h"
#include "constraints/jacobian_rows.h"

namespace lamina {

class DistanceConstraint final : public Constraint {
 public:
  // Throws std::invalid_argument if both ends are on the same body or both on the world, an
  // anchor is not finite, or L is not finite and positive.
  DistanceConstraint(const Anchor& a, const Anchor& b, double length);

  // One equality row.
  void write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                  std::vector<ConstraintRow>& rows) const override;
  const char* kind() const override { return "distance constraint"; }
  std::array<int, 2> bodies() const override { return {a_.body, b_.body}; }
  std::optional<std::array<Anchor, 2>> ends() const override { return std::array{a_, b_}; }

 private:
  Anchor a_;       // the first end
  Anchor b_;       // the second end
  double length_;  // L, the rod's length, in m
};

}  // namespace lamina
