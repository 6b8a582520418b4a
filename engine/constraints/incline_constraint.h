// Fig 3-1 and Fig 3-2: a body's centre of mass on an incline, the plane through p with normal N.
//
//   C = (x − p) · N                       (eq. 3-1, 3-13: ε)
//   Ċ = v · N                             (eq. 3-2)
//   J = [ Nᵀ  0ᵀ ]   (1 × 6, one-body row against the world)
//
// Two kinds, chosen when the constraint is made:
//   bilateral (Fig 3-1, the default)   C = 0: held on the line, as if tied to it
//     ζ = −β C / Δt                      (eq. 3-14, see constraint.h)
//     bounds (−∞, ∞): it may neither sink into nor leave the line (an equality row);
//     solving v(t+Δt)·N = ζ with v(t+Δt) = v + m⁻¹ (g + λ N) Δt gives λ (eq. 3-3, 3-4);
//     at rest on a slope of angle θ, λ = m g cos θ and the body slides with g sin θ.
//   one_sided (Fig 3-2)                C ≥ 0: it may leave the line, never cross it (eq. 3-17)
//     ζ = −C/Δt while C > 0, −β C/Δt once C ≤ 0   (eq. 3-18, 3-19; inequality_bias)
//     bounds [0, ∞): the line only pushes, and only while the body would otherwise cross it
//     (eq. 3-20..3-22: λ ≥ 0, W ≥ 0, λ W = 0)
#pragma once

#include "constraints/constraint.h"

namespace lamina {

enum class InclineKind {
  bilateral,  // (x − p)·N = 0, an equality row (Fig 3-1)
  one_sided   // (x − p)·N ≥ 0, an inequality row (Fig 3-2)
};

class InclineConstraint final : public Constraint {
 public:
  // Throws std::invalid_argument for a negative body index, a non-finite p or a non-unit N.
  InclineConstraint(int body, const Vec3& p, const Vec3& normal,
                    InclineKind kind = InclineKind::bilateral);

  // One row: an equality row, or for a one-sided incline an inequality row.
  void write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                  std::vector<ConstraintRow>& rows) const override;
  const char* kind() const override {
    return kind_ == InclineKind::bilateral ? "incline constraint" : "one-sided incline constraint";
  }
  std::array<int, 2> bodies() const override { return {world, body_}; }

 private:
  int body_;          // the body held, an index into the bodies
  Vec3 p_;            // p, a point of the incline, world frame, in m
  Vec3 normal_;       // N, the incline's unit normal, world frame; a one-sided body stays on its side
  InclineKind kind_;  // held on the line, or free to leave it
};

}  // namespace lamina
