// A revolute (pin) joint: anchor a on one body and anchor b on another body (or the world)
// stay at the same point of the x–y plane; the bodies turn freely about z.
//
//   C = p_b − p_a                       (x and y components: two equality rows)
//   row k (e_k = x̂, ŷ):  C_k = e_k · (p_b − p_a)
//   J_k = [ −e_kᵀ  −(r_a × e_k)ᵀ   e_kᵀ  (r_b × e_k)ᵀ ]   (jacobian_rows.h; 3D form, 6-vectors)
//   ζ_k = −β C_k / Δt                   (eq. 3-14, see constraint.h)
//   bounds (−∞, ∞)
// Lamina's scenes are planar, so the z row and the two out-of-plane angular rows of a 3D hinge
// are left out: nothing pushes the bodies out of the plane.
#pragma once

#include "constraints/constraint.h"
#include "constraints/jacobian_rows.h"

namespace lamina {

class RevoluteJoint final : public Constraint {
 public:
  // Throws std::invalid_argument if both anchors are on the same body or both on the world,
  // or an anchor is not finite. Make the anchors with anchor_at at the pivot's world point.
  RevoluteJoint(const Anchor& a, const Anchor& b);

  // Two equality rows, x then y.
  void write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                  std::vector<ConstraintRow>& rows) const override;
  const char* kind() const override { return "revolute joint"; }
  std::array<int, 2> bodies() const override { return {a_.body, b_.body}; }
  std::optional<std::array<Anchor, 2>> ends() const override { return std::array{a_, b_}; }

 private:
  Anchor a_;  // the pin on the first body (or the world)
  Anchor b_;  // the pin on the second body (or the world)
};

}  // namespace lamina
