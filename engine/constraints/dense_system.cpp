#include "constraints/dense_system.h"

namespace lamina {
namespace {

// Stacks one 6-vector per body into a 6n vector.
template <class PerBody>
Eigen::VectorXd stacked(const std::vector<RigidBody>& bodies, PerBody per_body) {
  Eigen::VectorXd result(6 * static_cast<Eigen::Index>(bodies.size()));
  for (size_t b = 0; b < bodies.size(); ++b) result.segment<6>(6 * b) = per_body(bodies[b]);
  return result;
}

// An s × 6n matrix from per-row sparse blocks: row i holds block(i, k) in body Jmap(i)[k]'s six
// columns ("Computing Jacobian"), and zeros elsewhere.
template <class Jmap, class Block>
Eigen::MatrixXd scatter(int row_count, int body_count, Jmap jmap, Block block) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(row_count, 6 * body_count);
  for (int i = 0; i < row_count; ++i) {
    for (int k = 0; k < 2; ++k) {
      const int body = jmap(i)[k];
      if (body >= 0) m.block<1, 6>(i, 6 * body) += block(i, k).transpose();
    }
  }
  return m;
}

}  // namespace

Eigen::VectorXd stacked_velocity(const std::vector<RigidBody>& bodies) {
  return stacked(bodies, velocity_of);
}

Eigen::VectorXd stacked_external_force(const std::vector<RigidBody>& bodies) {
  return stacked(bodies, external_force_of);
}

Eigen::MatrixXd dense_inverse_mass(const std::vector<RigidBody>& bodies) {
  const auto n = static_cast<Eigen::Index>(bodies.size());
  Eigen::MatrixXd m_inv = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  for (Eigen::Index b = 0; b < n; ++b) {
    // eq. 3-12: the body's diagonal block diag(m⁻¹ E, I⁻¹)
    m_inv.block<3, 3>(6 * b, 6 * b) = bodies[b].inverse_mass * identity3();
    m_inv.block<3, 3>(6 * b + 3, 6 * b + 3) = bodies[b].inverse_inertia_world;
  }
  return m_inv;
}

Eigen::MatrixXd dense_jacobian(const std::vector<ConstraintRow>& rows, int body_count) {
  // eq. 3-8
  return scatter(
      static_cast<int>(rows.size()), body_count, [&](int i) { return rows[i].Jmap; },
      [&](int i, int k) { return rows[i].Jsp[k]; });
}

Eigen::MatrixXd dense_jacobian(const Mlcp& mlcp) {
  // eq. 3-8
  return scatter(
      mlcp.row_count(), mlcp.body_count(), [&](int i) { return mlcp.bodies_of(i); },
      [&](int i, int k) { return mlcp.jacobian(i, k); });
}

Eigen::MatrixXd dense_b_transpose(const Mlcp& mlcp) {
  // the text's Convert: Bᵀ = J M⁻¹, block by block
  return scatter(
      mlcp.row_count(), mlcp.body_count(), [&](int i) { return mlcp.bodies_of(i); },
      [&](int i, int k) { return mlcp.b_block(i, k); });
}

DenseSystem build_dense_system(const std::vector<RigidBody>& bodies,
                               const std::vector<ConstraintRow>& rows, double dt) {
  DenseSystem sys;
  sys.J = dense_jacobian(rows, static_cast<int>(bodies.size()));
  sys.inverse_mass = dense_inverse_mass(bodies);
  // eq. 3-16: J B with B = M⁻¹ Jᵀ
  sys.JB = sys.J * sys.inverse_mass * sys.J.transpose();
  sys.zeta.resize(static_cast<Eigen::Index>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i) sys.zeta[i] = rows[i].zeta;
  const Eigen::VectorXd V = stacked_velocity(bodies);
  const Eigen::VectorXd F_ext = stacked_external_force(bodies);
  // eq. 3-16: η = ζ/Δt − J (V/Δt + M⁻¹ F_ext)
  sys.eta = sys.zeta / dt - sys.J * (V / dt + sys.inverse_mass * F_ext);
  return sys;
}

}  // namespace lamina
