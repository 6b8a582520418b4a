// Fig 3-1: a body held on an incline, its centre of mass on the plane through p with normal N.
//
//   C = (x − p) · N                 = 0   (eq. 3-1, 3-13: ε)
//   Ċ = v · N                       = 0   (eq. 3-2)
//   J = [ Nᵀ  0ᵀ ]   (1 × 6, one-body row against the world)
//   ζ = −β C / Δt                         (eq. 3-14, see constraint.h)
//   bounds (−∞, ∞): the body may neither sink into nor leave the incline (an equality row)
//   solving v(t+Δt)·N = ζ with v(t+Δt) = v + m⁻¹ (g + λ N) Δt gives λ (eq. 3-3, 3-4);
//   at rest on a slope of angle θ, λ = m g cos θ and the body slides with g sin θ.
#pragma once

#include "constraints/constraint.h"

namespace lamina {

class InclineConstraint final : public Constraint {
 public:
  // Throws std::invalid_argument for a negative body index, a non-finite p or a non-unit N.
  InclineConstraint(int body, const Vec3& p, const Vec3& normal);

  // One equality row.
  void write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                  std::vector<ConstraintRow>& rows) const override;
  const char* kind() const override { return "incline constraint"; }
  std::array<int, 2> bodies() const override { return {world, body_}; }

 private:
  int body_;     // the body held, an index into the bodies
  Vec3 p_;       // p, a point of the incline, world frame, in m
  Vec3 normal_;  // N, the incline's unit normal, world frame
};

}  // namespace lamina
