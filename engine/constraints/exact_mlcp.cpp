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

// Row i's LCP variables: p (its λ, or λ's positive part), then m and s where it has them.
struct Variables {
  Kind kind;
  int p, m, s;
};

Kind kind_of(const Mlcp& mlcp, int i) {
  if (mlcp.friction_of(i) >= 0) return Kind::friction;
  const double none = 0.0;
  const std::array<double, 2> b = mlcp.bounds(i, &none);
  if (b[0] == 0.0 && std::isinf(b[1]) && b[1] > 0.0) return Kind::one_sided;
  require(std::isinf(b[0]) && b[0] < 0.0 && std::isinf(b[1]) && b[1] > 0.0,
          "exact MLCP: row " + std::to_string(i) + " has bounds that are neither [0, ∞) nor "
          "(−∞, ∞) nor a friction row's");
  return Kind::equality;
}

// J B (eq. 3-16) from the rows' blocks: (J B)_ij = Σ J_i's block of a body · B_j's block of the
// same body, over the bodies rows i and j share. Rows that share no body give 0, so an island's
// rows cost their count squared, not the world's bodies.
Eigen::MatrixXd delassus(const Mlcp& mlcp) {
  const int n = mlcp.row_count();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    const std::array<int, 2> bi = mlcp.bodies_of(i);
    for (int j = 0; j < n; ++j) {
      const std::array<int, 2> bj = mlcp.bodies_of(j);
      for (int k = 0; k < 2; ++k) {
        for (int l = 0; l < 2; ++l) {
          if (bi[k] >= 0 && bi[k] == bj[l]) A(i, j) += mlcp.jacobian(i, k).dot(mlcp.b_block(j, l));
        }
      }
    }
  }
  return A;
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
  const int n = mlcp.row_count();
  const Eigen::MatrixXd JB = delassus(mlcp);
  bool equalities_only = true;
  for (int i = 0; i < n && equalities_only; ++i) equalities_only = kind_of(mlcp, i) == Kind::equality;
  if (equalities_only) {
    // No bounds: J B λ = η is a linear system, J B symmetric positive definite for independent
    // rows, solved by Cholesky with pivoting (LDLᵀ).
    Eigen::VectorXd eta(n);
    for (int i = 0; i < n; ++i) eta[i] = mlcp.eta(i);
    const auto solves = [&](const Eigen::VectorXd& lambda) {
      return lambda.allFinite() && (JB * lambda - eta).norm() <= 1e-9 * (1.0 + eta.norm());
    };
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(JB);
    ExactSolution out;
    out.lambda = ldlt.solve(eta);
    // Dependent rows (a straight bridge pinned at both ends: 11 pins' horizontal rows on 10
    // planks) make J B singular: LDLᵀ meets a pivot that is zero to round-off, and its λ, when
    // it gives one, loads the dependent rows arbitrarily. When J B λ = η still has solutions,
    // the one of least |λ| shares the load evenly among them; a complete orthogonal
    // decomposition finds it.
    const Eigen::VectorXd pivots = ldlt.vectorD().cwiseAbs();
    const bool singular = n > 0 && pivots.minCoeff() <= 1e-12 * pivots.maxCoeff();
    bool solved = !singular && ldlt.info() == Eigen::Success && solves(out.lambda);
    if (!solved) {
      out.lambda = JB.completeOrthogonalDecomposition().solve(eta);
      solved = solves(out.lambda);
    }
    out.status = solved ? LemkeStatus::solved : LemkeStatus::ray;
    if (!solved) out.lambda.setZero();
    return out;
  }
  std::vector<Variables> vars;
  int count = 0;
  for (int i = 0; i < n; ++i) {
    const Kind k = kind_of(mlcp, i);
    Variables v{k, count++, -1, -1};
    if (k != Kind::one_sided) v.m = count++;
    if (k == Kind::friction) v.s = count++;
    vars.push_back(v);
  }
  // λ = P y: each row's λ from its variables.
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(n, count);
  for (int i = 0; i < n; ++i) {
    P(i, vars[i].p) = 1.0;
    if (vars[i].m >= 0) P(i, vars[i].m) = -1.0;
  }
  const Eigen::MatrixXd W = JB * P;  // W = W·y − η, row by row
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(count, count);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(count);
  for (int i = 0; i < n; ++i) {
    const Variables& v = vars[i];
    const double eta = mlcp.eta(i);
    M.row(v.p) = W.row(i);
    q[v.p] = -eta;
    if (v.kind == Kind::one_sided) continue;
    M.row(v.m) = -W.row(i);
    q[v.m] = eta;
    if (v.kind != Kind::friction) continue;
    M(v.p, v.s) += 1.0;
    M(v.m, v.s) += 1.0;
    // μ Σ λc − p − m ≥ 0 over the contact rows that bound it
    const int first = mlcp.friction_of(i);
    for (int c = first; c < first + mlcp.friction_count(i); ++c) M.row(v.s) += mlcp.mu(i) * P.row(c);
    M(v.s, v.p) -= 1.0;
    M(v.s, v.m) -= 1.0;
  }
  const LemkeResult r = solve_lcp_lemke(M, q);
  ExactSolution out;
  out.status = r.status;
  out.pivots = r.pivots;
  out.lambda = r.status == LemkeStatus::solved ? Eigen::VectorXd(P * r.z) : Eigen::VectorXd::Zero(n);
  return out;
}

}  // namespace lamina
