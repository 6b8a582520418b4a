#include "constraints/mlcp.h"

#include <algorithm>
#include <cmath>

namespace lamina {

Vec6 inverse_mass_times(const RigidBody& body, const Vec6& block) {
  Vec6 result;
  // eq. 3-12: M⁻¹ = diag(m⁻¹ E, I⁻¹) for this body
  result.head<3>() = body.inverse_mass * block.head<3>();
  result.tail<3>() = body.inverse_inertia_world * block.tail<3>();
  return result;
}

Vec6 velocity_of(const RigidBody& body) {
  Vec6 v;
  v << body.v, body.angular_velocity;
  return v;
}

Vec6 external_force_of(const RigidBody& body) {
  Vec6 f;
  f << body.force, body.torque;
  return f;
}

double row_times(const ConstraintRow& row, const std::vector<Vec6>& per_body) {
  double sum = row.Jsp[0].dot(per_body[row.Jmap[0]]);
  if (!row.is_one_body()) sum += row.Jsp[1].dot(per_body[row.Jmap[1]]);
  return sum;
}

Mlcp assemble_mlcp(const std::vector<RigidBody>& bodies, std::vector<ConstraintRow> rows,
                   double dt) {
  Mlcp mlcp;
  mlcp.body_count = static_cast<int>(bodies.size());
  // V/Δt + M⁻¹ F_ext per body: the velocity each body would reach without constraints, per Δt.
  std::vector<Vec6> unconstrained(bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    unconstrained[b] = velocity_of(bodies[b]) / dt +
                       inverse_mass_times(bodies[b], external_force_of(bodies[b]));
  }
  const auto s = static_cast<Eigen::Index>(rows.size());
  mlcp.eta.resize(s);
  mlcp.d.resize(s);
  mlcp.Bsp.resize(rows.size());
  for (Eigen::Index i = 0; i < s; ++i) {
    const ConstraintRow& row = rows[i];
    // The text's Convert: Bᵀ_i = J_i M⁻¹, block by block.
    mlcp.Bsp[i][0] = inverse_mass_times(bodies[row.Jmap[0]], row.Jsp[0]);
    mlcp.Bsp[i][1] = row.is_one_body() ? Vec6::Zero()
                                       : inverse_mass_times(bodies[row.Jmap[1]], row.Jsp[1]);
    // d_i = J_i · B_i
    mlcp.d[i] = row.Jsp[0].dot(mlcp.Bsp[i][0]) + row.Jsp[1].dot(mlcp.Bsp[i][1]);
    // eq. 3-16: η = ζ/Δt − J (V/Δt + M⁻¹ F_ext)
    mlcp.eta[i] = row.zeta / dt - row_times(row, unconstrained);
  }
  mlcp.rows = std::move(rows);
  return mlcp;
}

std::vector<Vec6> transpose_multiply(const Mlcp& mlcp, const Eigen::VectorXd& lambda) {
  std::vector<Vec6> a(mlcp.body_count, Vec6::Zero());
  for (size_t i = 0; i < mlcp.rows.size(); ++i) {
    const ConstraintRow& row = mlcp.rows[i];
    a[row.Jmap[0]] += lambda[i] * mlcp.Bsp[i][0];
    if (!row.is_one_body()) a[row.Jmap[1]] += lambda[i] * mlcp.Bsp[i][1];
  }
  return a;
}

Eigen::VectorXd complementarity_slack(const Mlcp& mlcp, const Eigen::VectorXd& lambda) {
  const std::vector<Vec6> a = transpose_multiply(mlcp, lambda);
  Eigen::VectorXd w(lambda.size());
  // eq. 3-23: W = J B λ − η
  for (size_t i = 0; i < mlcp.rows.size(); ++i) w[i] = row_times(mlcp.rows[i], a) - mlcp.eta[i];
  return w;
}

std::array<double, 2> row_bounds(const ConstraintRow& row, const Eigen::VectorXd& lambda) {
  if (row.friction_of < 0) return {row.lambda_min, row.lambda_max};
  // eq. 3-26: a friction row is bounded by ±μ λc of its contact row
  const double limit = row.mu * lambda[row.friction_of];
  return {-limit, limit};
}

double mlcp_residual(const Mlcp& mlcp, const Eigen::VectorXd& lambda) {
  const Eigen::VectorXd w = complementarity_slack(mlcp, lambda);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    const auto [lo, hi] = row_bounds(mlcp.rows[i], lambda);
    // eq. 3-24: W = 0 inside the bounds, W ≥ 0 at λ⁻, W ≤ 0 at λ⁺
    double violation = w[i];
    if (lambda[i] <= lo) violation = std::min(w[i], 0.0);
    if (lambda[i] >= hi) violation = std::max(w[i], 0.0);
    if (lo == hi) violation = 0.0;
    sum += violation * violation;
  }
  return std::sqrt(sum);
}

void apply_constraint_forces(std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                             const Eigen::VectorXd& lambda) {
  for (size_t i = 0; i < rows.size(); ++i) {
    for (int k = 0; k < 2; ++k) {
      if (rows[i].Jmap[k] < 0) continue;
      RigidBody& body = bodies[rows[i].Jmap[k]];
      // eq. 3-11: F_c = Jᵀ λ
      body.force += lambda[i] * rows[i].Jsp[k].head<3>();
      body.torque += lambda[i] * rows[i].Jsp[k].tail<3>();
    }
  }
}

}  // namespace lamina
