#include "constraints/pgs_solver.h"

#include <algorithm>

namespace lamina {
namespace {

// One Gauss-Seidel sweep over the rows, each λ_i projected onto its bounds.
void sweep(const Mlcp& mlcp, Eigen::VectorXd& lambda, std::vector<Vec6>& a) {
  for (size_t i = 0; i < mlcp.rows.size(); ++i) {
    const ConstraintRow& row = mlcp.rows[i];
    const int b1 = row.Jmap[0];
    const int b2 = row.Jmap[1];
    double j_a = row.Jsp[0].dot(a[b1]);
    if (b2 >= 0) j_a += row.Jsp[1].dot(a[b2]);
    // Delta = (η_i − J_i · a) / d_i, Gauss-Seidel's (b_i − Σ_j A_ij λ_j) / A_ii
    const double delta = (mlcp.eta[i] - j_a) / mlcp.d[i];
    const double old = lambda[i];
    const auto [lo, hi] = row_bounds(row, lambda);
    lambda[i] = std::max(lo, std::min(old + delta, hi));
    const double diff = lambda[i] - old;
    a[b1] += diff * mlcp.Bsp[i][0];
    if (b2 >= 0) a[b2] += diff * mlcp.Bsp[i][1];
  }
}

}  // namespace

PgsResult solve_pgs(const Mlcp& mlcp, const Eigen::VectorXd& lambda_exp, const PgsSettings& settings) {
  PgsResult result;
  result.lambda = lambda_exp;
  std::vector<Vec6> a = transpose_multiply(mlcp, result.lambda);
  run_sweeps(
      settings, [&] { sweep(mlcp, result.lambda, a); },
      [&] { return mlcp_residual(mlcp, result.lambda); }, result);
  return result;
}

}  // namespace lamina
