#include "constraints/exact_mlcp.h"

#include <cmath>
#include <string>
#include <vector>

#include "constraints/dense_system.h"
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

}  // namespace

ExactSolution solve_mlcp_exactly(const Mlcp& mlcp) {
  const int n = mlcp.row_count();
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
  const Eigen::MatrixXd JB = dense_jacobian(mlcp) * dense_b_transpose(mlcp).transpose();
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
