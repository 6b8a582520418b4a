#include "constraints/pgs_solver.h"

#include <algorithm>

namespace lamina {
namespace {

// Row i of a sweep, on the a_b of its two bodies (a2 unused for a one-body row).
template <int N>
void solve_row(const PackedRow<N>& row, size_t i, double* lambda, Block<N>& a1, Block<N>& a2) {
  const bool two_bodies = row.two_bodies();
  // Δ = (η_i − J_i · a) / d_i; 1/d_i is computed once per row when the row is assembled, so the
  // sweep multiplies instead of dividing
  const double delta = (row.eta - row_dot<N>(row.J, a1, a2, two_bodies)) * row.inverse_d;
  const double old = lambda[i];
  const auto [lo, hi] = bounds_of(row, lambda);
  lambda[i] = std::max(lo, std::min(old + delta, hi));
  const double diff = lambda[i] - old;
  a1 += diff * row.B[0];
  if (two_bodies) a2 += diff * row.B[1];
}

// One Gauss-Seidel sweep over the rows, each λ_i projected onto its bounds. Consecutive rows on
// the same bodies (a pair's contact rows and their friction rows) keep their bodies' a_b in
// local variables: the same arithmetic, without a trip through memory per row.
template <int N>
void sweep(const PackedRows<N>& packed, std::vector<Block<N>>& a_of_body, double* lambda) {
  // raw pointers: the stores to λ cannot then be taken to move the vectors' buffers
  const PackedRow<N>* rows = packed.data();
  Block<N>* a = a_of_body.data();
  const size_t count = packed.size();
  for (size_t i = 0; i < count;) {
    const int b1 = rows[i].map[0];
    const int b2 = rows[i].map[1];
    Block<N> a1 = a[b1];
    Block<N> a2 = b2 >= 0 ? a[b2] : Block<N>::Zero();
    for (; i < count && rows[i].map[0] == b1 && rows[i].map[1] == b2; ++i) {
      solve_row(rows[i], i, lambda, a1, a2);
    }
    a[b1] = a1;
    if (b2 >= 0) a[b2] = a2;
  }
}

}  // namespace

template <>
std::vector<Block<3>>& PgsSolver::a<3>() { return planar_a_; }
template <>
std::vector<Block<6>>& PgsSolver::a<6>() { return general_a_; }

void PgsSolver::solve(const Mlcp& mlcp, double* lambda, const SweepSettings& settings,
                      SweepResult& result) {
  const bool measure = settings.record_residuals || settings.tolerance > 0.0;
  mlcp.visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    planar_ = N == 3;
    std::vector<Block<N>>& a_of_body = a<N>();
    // λ = λ_exp: a = B λ (the text's TransposeMultiply)
    transpose_multiply(rows, mlcp.body_count(), lambda, a_of_body);
    for (int iter = 0; iter < settings.iterations; ++iter) {
      sweep(rows, a_of_body, lambda);
      result.iterations = iter + 1;
      if (!measure) continue;
      const double r = mlcp.residual(lambda);
      if (settings.record_residuals) result.residuals.push_back(r);
      if (settings.tolerance > 0.0 && r <= settings.tolerance) break;
    }
  });
}

Vec6 PgsSolver::velocity_change(int body) const {
  return planar_ ? widen(planar_a_[body]) : widen(general_a_[body]);
}

SweepResult solve_pgs(const Mlcp& mlcp, const Eigen::VectorXd& lambda_exp,
                      const SweepSettings& settings) {
  PgsSolver solver;
  SweepResult result;
  result.lambda = lambda_exp;
  solver.solve(mlcp, result.lambda.data(), settings, result);
  return result;
}

}  // namespace lamina
