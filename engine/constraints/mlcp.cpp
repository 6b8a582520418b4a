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
  v.head<3>() = body.v;
  v.tail<3>() = body.angular_velocity;
  return v;
}

Vec6 external_force_of(const RigidBody& body) {
  Vec6 f;
  f.head<3>() = body.force;
  f.tail<3>() = body.torque;
  return f;
}

double row_times(const ConstraintRow& row, const std::vector<Vec6>& per_body) {
  double sum = ordered_dot<6>(row.Jsp[0], per_body[row.Jmap[0]]);
  if (!row.is_one_body()) sum += ordered_dot<6>(row.Jsp[1], per_body[row.Jmap[1]]);
  return sum;
}

void unconstrained_velocities(const std::vector<RigidBody>& bodies, double dt,
                              std::vector<Vec6>& out) {
  out.resize(bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    // eq. 3-16: V/Δt + M⁻¹ F_ext, the bracket of η, body by body
    out[b] = velocity_of(bodies[b]) / dt +
             inverse_mass_times(bodies[b], external_force_of(bodies[b]));
  }
}

Mlcp assemble_mlcp(const std::vector<RigidBody>& bodies, std::vector<ConstraintRow> rows,
                   double dt) {
  std::vector<Vec6> unconstrained;
  unconstrained_velocities(bodies, dt, unconstrained);
  return assemble_mlcp(bodies, std::move(rows), unconstrained, dt);
}

Mlcp assemble_mlcp(const std::vector<RigidBody>& bodies, std::vector<ConstraintRow> rows,
                   const std::vector<Vec6>& unconstrained, double dt) {
  Mlcp mlcp;
  mlcp.body_count = static_cast<int>(bodies.size());
  const auto s = static_cast<Eigen::Index>(rows.size());
  mlcp.eta.resize(s);
  mlcp.d.resize(s);
  mlcp.Bsp.resize(rows.size());
  for (Eigen::Index i = 0; i < s; ++i) {
    const RowTerms<6> terms = assemble_row<6>(bodies, rows[i], unconstrained, dt);
    mlcp.Bsp[i] = terms.B;
    mlcp.eta[i] = terms.eta;
    mlcp.d[i] = terms.d;
  }
  mlcp.rows = std::move(rows);
  return mlcp;
}

std::vector<Vec6> transpose_multiply(const Mlcp& mlcp,
                                     const Eigen::Ref<const Eigen::VectorXd>& lambda) {
  std::vector<Vec6> a(mlcp.body_count, Vec6::Zero());
  for (size_t i = 0; i < mlcp.rows.size(); ++i) {
    const ConstraintRow& row = mlcp.rows[i];
    a[row.Jmap[0]] += lambda[i] * mlcp.Bsp[i][0];
    if (!row.is_one_body()) a[row.Jmap[1]] += lambda[i] * mlcp.Bsp[i][1];
  }
  return a;
}

Eigen::VectorXd complementarity_slack(const Mlcp& mlcp,
                                      const Eigen::Ref<const Eigen::VectorXd>& lambda) {
  const std::vector<Vec6> a = transpose_multiply(mlcp, lambda);
  Eigen::VectorXd w(lambda.size());
  // eq. 3-23: W = J B λ − η
  for (size_t i = 0; i < mlcp.rows.size(); ++i) w[i] = row_times(mlcp.rows[i], a) - mlcp.eta[i];
  return w;
}

std::array<double, 2> row_bounds(const ConstraintRow& row,
                                 const Eigen::Ref<const Eigen::VectorXd>& lambda) {
  return bounds_of(row, lambda.data());
}

double mlcp_residual(const Mlcp& mlcp, const Eigen::Ref<const Eigen::VectorXd>& lambda) {
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
                             const Eigen::Ref<const Eigen::VectorXd>& lambda) {
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
