#include "constraints/constraint.h"

#include "kinematics/require.h"

namespace lamina {

double equality_bias(double C, double dt, double beta) {
  // eq. 3-14: v(t+Δt)·N = −β ε, per unit of Δt
  return -beta * C / dt;
}

double inequality_bias(double C, double dt, double beta) {
  // eq. 3-18, 3-19: C + Δt J V(t+Δt) ≥ 0 lets an open gap close in one step
  if (C > 0.0) return -C / dt;
  return equality_bias(C, dt, beta);
}

void require_body_pair(int body_a, int body_b, const std::string& what) {
  require(body_a >= world && body_b >= world,
          what + ": body indices must be ≥ 0 or −1 (world), got " + std::to_string(body_a) +
              " and " + std::to_string(body_b));
  require(body_a != body_b, what + ": needs two different bodies (or a body and the world), got " +
                                (body_a == world ? std::string("the world") : "body " + std::to_string(body_a)) +
                                " twice");
}

std::vector<ConstraintRow> write_all_rows(const std::vector<RigidBody>& bodies,
                                          const ConstraintList& constraints, double dt,
                                          double beta) {
  std::vector<ConstraintRow> rows;
  for (const auto& constraint : constraints) constraint->write_rows(bodies, dt, beta, rows);
  return rows;
}

}  // namespace lamina
