#include "constraints/gauss_seidel.h"

#include <cassert>

namespace lamina {
namespace {

// One sweep in row order, each λ_i using the λ_j already updated in this sweep.
void sweep(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, Eigen::VectorXd& lambda) {
  for (Eigen::Index i = 0; i < b.size(); ++i) {
    // Delta = (b_i − Σ_j A_ij λ_j) / A_ii, the text's GaussSeidel
    const double delta = (b[i] - A.row(i).dot(lambda)) / A(i, i);
    lambda[i] += delta;
  }
}

}  // namespace

PgsResult gauss_seidel(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                       const Eigen::VectorXd& lambda_exp, const PgsSettings& settings) {
  assert(A.rows() == A.cols() && A.rows() == b.size() && b.size() == lambda_exp.size());
  PgsResult result;
  result.lambda = lambda_exp;
  run_sweeps(
      settings, [&] { sweep(A, b, result.lambda); },
      [&] { return (A * result.lambda - b).norm(); }, result);
  return result;
}

}  // namespace lamina
