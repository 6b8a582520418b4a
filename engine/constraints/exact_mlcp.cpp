#include "constraints/exact_mlcp.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include "kinematics/require.h"

namespace lamina {
namespace {

enum class Kind { one_sided, equality, friction };

Kind kind_of(const Mlcp& mlcp, int i) {
  if (mlcp.friction_of(i) >= 0) return Kind::friction;
  const double none = 0.0;
  const std::array<double, 2> b = mlcp.bounds(i, &none);
  if (b[0] == 0.0 && std::isinf(b[1]) && b[1] > 0.0) return Kind::one_sided;
  if (!(std::isinf(b[0]) && b[0] < 0.0 && std::isinf(b[1]) && b[1] > 0.0)) {
    require(false, "exact MLCP: row " + std::to_string(i) + " has bounds that are neither [0, ∞) "
                   "nor (−∞, ∞) nor a friction row's");
  }
  return Kind::equality;
}

}  // namespace

bool has_exact_form(const Mlcp& mlcp) {
  for (int i = 0; i < mlcp.row_count(); ++i) {
    if (mlcp.friction_of(i) >= 0) continue;
    const double none = 0.0;
    const std::array<double, 2> b = mlcp.bounds(i, &none);
    const bool one_sided = b[0] == 0.0 && std::isinf(b[1]) && b[1] > 0.0;
    const bool equality = std::isinf(b[0]) && b[0] < 0.0 && std::isinf(b[1]) && b[1] > 0.0;
    if (!one_sided && !equality) return false;
  }
  return true;
}

ExactSolution solve_mlcp_exactly(const Mlcp& mlcp) {
  ExactMlcpSolver solver;
  ExactSolution out;
  out.status = solver.solve(mlcp);
  out.lambda = solver.lambda();
  out.pivots = solver.pivots();
  return out;
}

// J B (eq. 3-16) from the rows' blocks: (J B)_ij = Σ J_i's block of a body · B_j's block of the
// same body, over the bodies rows i and j share. Rows that share no body give 0, so an island's
// rows cost their count squared, not the world's bodies.
void ExactMlcpSolver::delassus(const Mlcp& mlcp) {
  const int n = mlcp.row_count();
  JB_.setZero(n, n);
  for (int i = 0; i < n; ++i) {
    const std::array<int, 2> bi = mlcp.bodies_of(i);
    for (int j = 0; j < n; ++j) {
      const std::array<int, 2> bj = mlcp.bodies_of(j);
      for (int k = 0; k < 2; ++k) {
        for (int l = 0; l < 2; ++l) {
          if (bi[k] >= 0 && bi[k] == bj[l]) JB_(i, j) += mlcp.jacobian(i, k).dot(mlcp.b_block(j, l));
        }
      }
    }
  }
}

LemkeStatus ExactMlcpSolver::solve(const Mlcp& mlcp) {
  const int n = mlcp.row_count();
  pivots_ = 0;
  delassus(mlcp);
  eta_.resize(n);
  for (int i = 0; i < n; ++i) eta_[i] = mlcp.eta(i);
  bool equalities_only = true;
  for (int i = 0; i < n && equalities_only; ++i) equalities_only = kind_of(mlcp, i) == Kind::equality;
  if (equalities_only) return solve_equalities(mlcp);

  vars_.clear();
  int count = 0;
  for (int i = 0; i < n; ++i) {
    const Kind k = kind_of(mlcp, i);
    Variables v{count++, -1, -1};
    if (k != Kind::one_sided) v.m = count++;
    if (k == Kind::friction) v.s = count++;
    vars_.push_back(v);
  }
  // λ = P y, each row's λ from its variables (λ_i = p_i − m_i), so J B λ − η reads, row by
  // row, W y − η with W = J B P: W's column p_k is J B's column k, m_k its negative, s_k zero.
  M_.setZero(count, count);
  q_.setZero(count);
  for (int i = 0; i < n; ++i) {
    const Variables& v = vars_[static_cast<std::size_t>(i)];
    for (int k = 0; k < n; ++k) {
      const Variables& u = vars_[static_cast<std::size_t>(k)];
      M_(v.p, u.p) = JB_(i, k);
      if (u.m >= 0) M_(v.p, u.m) = -JB_(i, k);
    }
    q_[v.p] = -eta_[i];
    if (v.m < 0) continue;
    M_.row(v.m) = -M_.row(v.p);
    q_[v.m] = eta_[i];
    if (v.s < 0) continue;
    M_(v.p, v.s) += 1.0;
    M_(v.m, v.s) += 1.0;
    // μ Σ λc − p − m ≥ 0 over the contact rows that bound it
    const int first = mlcp.friction_of(i);
    for (int c = first; c < first + mlcp.friction_count(i); ++c) {
      const Variables& u = vars_[static_cast<std::size_t>(c)];
      M_(v.s, u.p) += mlcp.mu(i);
      if (u.m >= 0) M_(v.s, u.m) -= mlcp.mu(i);
    }
    M_(v.s, v.p) -= 1.0;
    M_(v.s, v.m) -= 1.0;
  }
  const LemkeStatus status = lemke_.solve(M_, q_);
  pivots_ = lemke_.pivots();
  lambda_.setZero(n);
  if (status != LemkeStatus::solved) return status;
  const Eigen::VectorXd& z = lemke_.z();
  for (int i = 0; i < n; ++i) {
    const Variables& v = vars_[static_cast<std::size_t>(i)];
    lambda_[i] = v.m >= 0 ? z[v.p] - z[v.m] : z[v.p];
  }
  return status;
}

// No bounds: J B λ = η is a linear system, J B symmetric positive definite for independent rows,
// solved by Cholesky with pivoting (LDLᵀ).
LemkeStatus ExactMlcpSolver::solve_equalities(const Mlcp& mlcp) {
  const int n = mlcp.row_count();
  const auto solves = [&] {
    if (!lambda_.allFinite()) return false;
    residual_.noalias() = JB_ * lambda_;
    residual_ -= eta_;
    return residual_.norm() <= 1e-9 * (1.0 + eta_.norm());
  };
  ldlt_.compute(JB_);
  lambda_ = ldlt_.solve(eta_);
  // Dependent rows (a straight bridge pinned at both ends: 11 pins' horizontal rows on 10
  // planks) make J B singular: LDLᵀ meets a pivot that is zero to round-off, and its λ, when
  // it gives one, loads the dependent rows arbitrarily. When J B λ = η still has solutions,
  // the one of least |λ| shares the load evenly among them; a complete orthogonal
  // decomposition finds it.
  bool singular = false;
  if (n > 0) {
    const auto pivots = ldlt_.vectorD().cwiseAbs();
    singular = pivots.minCoeff() <= 1e-12 * pivots.maxCoeff();
  }
  bool solved = !singular && ldlt_.info() == Eigen::Success && solves();
  if (!solved) {
    lambda_ = JB_.completeOrthogonalDecomposition().solve(eta_);
    solved = solves();
  }
  if (!solved) {
    lambda_.setZero(n);
    return LemkeStatus::ray;
  }
  return LemkeStatus::solved;
}

}  // namespace lamina
