#include "constraints/gauss_seidel.h"

#include <cassert>

namespace lamina {

SweepResult gauss_seidel(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                         const Eigen::VectorXd& lambda_exp, const SweepSettings& settings) {
  assert(A.rows() == A.cols() && A.rows() == b.size() && b.size() == lambda_exp.size());
  SweepResult result;
  result.lambda = lambda_exp;
  Eigen::VectorXd& lambda = result.lambda;
  while (result.iterations < settings.iterations) {
    // one sweep in row order, each λ_i using the λ_j already updated in this sweep:
    // λ_i += (b_i − Σ_j A_ij λ_j) / A_ii, the text's GaussSeidel
    for (Eigen::Index i = 0; i < b.size(); ++i) lambda[i] += (b[i] - A.row(i).dot(lambda)) / A(i, i);
    ++result.iterations;
    if (!settings.record_sweeps && settings.tolerance <= 0.0) continue;
    const double residual = (A * lambda - b).norm();
    if (settings.record_sweeps) {
      result.residuals.push_back(residual);
      result.lambdas.push_back(lambda);
    }
    if (settings.tolerance > 0.0 && residual <= settings.tolerance) break;
  }
  return result;
}

}  // namespace lamina
