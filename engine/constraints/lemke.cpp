#include "constraints/lemke.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kinematics/require.h"

namespace lamina {

LemkeResult solve_lcp_lemke(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, int max_pivots) {
  LemkeSolver solver;
  LemkeResult result;
  result.status = solver.solve(M, q, max_pivots);
  result.z = solver.z();
  result.pivots = solver.pivots();
  return result;
}

LemkeStatus LemkeSolver::solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, int max_pivots) {
  const int n = static_cast<int>(q.size());
  if (M.rows() != n || M.cols() != n) {  // the message only when it is needed: no allocation
    require(false, "Lemke: M is " + std::to_string(M.rows()) + " × " + std::to_string(M.cols()) +
                       ", q has " + std::to_string(n) + " entries");
  }
  if (!M.allFinite() || !q.allFinite()) require(false, "Lemke: M and q must be finite");
  z_.setZero(n);
  pivots_ = 0;
  if (n == 0 || q.minCoeff() >= 0.0) return LemkeStatus::solved;  // z = 0, w = q ≥ 0
  if (max_pivots <= 0) max_pivots = 50 * (n + 1);

  start(M, q);
  // z0 enters where q is most negative: every w becomes ≥ 0, that one 0, and leaves.
  int row = 0;
  for (int i = 1; i < n; ++i) {
    if (q[i] < q[row]) row = i;
  }
  int leaving = basis_[static_cast<std::size_t>(row)];
  pivot(row, z0());
  pivots_ = 1;
  while (pivots_ < max_pivots) {
    const int entering = complement(leaving);
    row = leaving_row(entering);
    if (row < 0) return LemkeStatus::ray;
    leaving = basis_[static_cast<std::size_t>(row)];
    pivot(row, entering);
    ++pivots_;
    if (leaving == z0()) {
      read_z();
      if (solves(M, q)) return LemkeStatus::solved;
      z_.setZero();
      return LemkeStatus::inaccurate;
    }
  }
  return LemkeStatus::out_of_pivots;
}

void LemkeSolver::start(const Eigen::MatrixXd& M, const Eigen::VectorXd& q) {
  n_ = static_cast<int>(q.size());
  t_.setZero(n_, 2 * n_ + 2);
  t_.leftCols(n_).setIdentity();
  t_.middleCols(n_, n_) = -M;
  t_.col(2 * n_).setConstant(-1.0);
  t_.col(2 * n_ + 1) = q;
  basis_.resize(static_cast<std::size_t>(n_));
  basic_.assign(static_cast<std::size_t>(2 * n_ + 1), 0);
  for (int i = 0; i < n_; ++i) {  // every w basic
    basis_[static_cast<std::size_t>(i)] = i;
    basic_[static_cast<std::size_t>(i)] = 1;
  }
}

// Makes `variable` basic in `row` (Gauss-Jordan on the whole tableau). Every other row i loses
// t(i, variable) times the pivot row, column by column down the column-major tableau (row by row
// it strode across memory: 5× the time). A basic variable's column is a unit vector and stays
// one (its entry in the pivot row is 0), and the entering variable's becomes e_row: only the
// other columns and the values are updated, half the work.
void LemkeSolver::pivot(int row, int variable) {
  t_.row(row) /= t_(row, variable);
  factors_ = t_.col(variable);
  factors_[row] = 0.0;  // the pivot row itself stays
  basic_[static_cast<std::size_t>(basis_[static_cast<std::size_t>(row)])] = 0;
  basic_[static_cast<std::size_t>(variable)] = 1;
  basis_[static_cast<std::size_t>(row)] = variable;
  for (int j = 0; j < 2 * n_ + 2; ++j) {
    if (j == 2 * n_ + 1 || !basic_[static_cast<std::size_t>(j)]) t_.col(j) -= t_(row, j) * factors_;
  }
  t_.col(variable).setZero();
  t_(row, variable) = 1.0;
}

// The row that leaves when `variable` enters: the least ratio value/column over the rows whose
// column is positive; ties go to z0's row, then lexicographically by B⁻¹'s row over the column
// (the w block of the tableau), which cannot tie. −1: no positive entry (a ray).
int LemkeSolver::leaving_row(int variable) const {
  const double eps = 1e-12 * std::max(1.0, t_.col(variable).cwiseAbs().maxCoeff());
  int best = -1;
  for (int i = 0; i < n_; ++i) {
    if (t_(i, variable) <= eps) continue;
    if (best < 0 || lexicographically_less(i, best, variable)) best = i;
  }
  return best;
}

// Whether row a's ratio vector (value, B⁻¹ row) / column is less than row b's.
bool LemkeSolver::lexicographically_less(int a, int b, int variable) const {
  const double ca = t_(a, variable), cb = t_(b, variable);
  const double ra = value(a) / ca, rb = value(b) / cb;
  const double tolerance = 1e-12 * std::max({1.0, std::abs(ra), std::abs(rb)});
  if (ra < rb - tolerance) return true;
  if (ra > rb + tolerance) return false;
  const int basic_a = basis_[static_cast<std::size_t>(a)], basic_b = basis_[static_cast<std::size_t>(b)];
  if (basic_a == z0()) return true;  // z0 leaving ends the method
  if (basic_b == z0()) return false;
  for (int j = 0; j < n_; ++j) {
    const double la = t_(a, j) / ca, lb = t_(b, j) / cb;
    if (la != lb) return la < lb;
  }
  return false;
}

// z from the basic variables' values: a z basic in a row takes that row's value, the rest 0.
void LemkeSolver::read_z() {
  z_.setZero(n_);
  for (int i = 0; i < n_; ++i) {
    const int v = basis_[static_cast<std::size_t>(i)];
    if (v >= n_ && v < 2 * n_) z_[v - n_] = value(i);
  }
}

// Whether z solves the LCP to round-off: z ≥ 0, w = M z + q ≥ 0 and min(z_i, w_i) = 0, each
// to 1e-9 of its own scale: z's is max(1, |z|∞); w_i's is its row's, max(1, |q_i|, Σ_j |M_ij z_j|),
// what rounding in M z + q is relative to. One scale for every row would mix units: the exact
// MLCP's rows are velocities (J B λ − η) and its friction rows forces (μ λ_n − λ_t), and a body a
// million times lighter than another makes the first 1e12 times the second (found by the physics
// fuzzer: a friction row 0.04 N past μ λ_n = 0 passed a shared scale of 2e12).
bool LemkeSolver::solves(const Eigen::MatrixXd& M, const Eigen::VectorXd& q) {
  w_.noalias() = M * z_;
  w_ += q;
  const double z_scale = std::max(1.0, z_.cwiseAbs().maxCoeff());
  terms_.setZero(n_);  // Σ_j |M_ij z_j| per row, column by column (no |M| made)
  for (int j = 0; j < n_; ++j) {
    if (z_[j] != 0.0) terms_ += M.col(j).cwiseAbs() * std::abs(z_[j]);
  }
  for (int i = 0; i < n_; ++i) {
    const double w_scale = std::max({1.0, std::abs(q[i]), terms_[i]});
    if (z_[i] < -1e-9 * z_scale || w_[i] < -1e-9 * w_scale) return false;
    if (std::min(z_[i] / z_scale, w_[i] / w_scale) > 1e-9) return false;  // complementary
  }
  return true;
}

}  // namespace lamina
