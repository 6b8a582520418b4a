#include "constraints/pgs_solver.h"

#include <algorithm>

namespace lamina {
namespace {

// One Gauss-Seidel sweep over the rows, each λ_i projected onto its bounds. Consecutive rows on
// the same bodies (a pair's contact rows and their friction rows) keep their bodies' a_b in
// local variables: the same arithmetic, without a trip through memory per row.
template <int N, bool ClampIncrement>
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
      pgs_row<N, ClampIncrement>(rows[i], i, lambda, a1, a2);
    }
    a[b1] = a1;
    if (b2 >= 0) a[b2] = a2;
  }
}

// The pitfall lambda-b1: the text's TransposeMultiply as written, scaling row i's blocks by
// λ[b1] and λ[b2], λ indexed by body instead of by row. Where a body index is past the rows the
// text reads beyond λ; here it wraps round to row b mod s, so the slip stays a wrong number and
// not a crash.
template <int N>
void transpose_multiply_text_slip(const PackedRows<N>& rows, int body_count, const double* lambda,
                                  std::vector<Block<N>>& a) {
  a.assign(static_cast<std::size_t>(body_count), Block<N>::Zero());
  const std::size_t s = rows.size();
  for (std::size_t i = 0; i < s; ++i) {
    const PackedRow<N>& row = rows[i];
    a[row.map[0]] += lambda[static_cast<std::size_t>(row.map[0]) % s] * row.B[0];
    if (row.two_bodies()) a[row.map[1]] += lambda[static_cast<std::size_t>(row.map[1]) % s] * row.B[1];
  }
}

}  // namespace

template <>
std::vector<Block<3>>& PgsSolver::a<3>() { return planar_a_; }
template <>
std::vector<Block<6>>& PgsSolver::a<6>() { return general_a_; }

void PgsSolver::solve(const Mlcp& mlcp, double* lambda, const SweepSettings& settings,
                      SweepResult& result, Pitfalls pitfalls) {
  const bool measure = settings.record_sweeps || settings.tolerance > 0.0;
  mlcp.visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    planar_ = N == 3;
    std::vector<Block<N>>& a_of_body = a<N>();
    // λ = λ_exp: a = B λ (the text's TransposeMultiply)
    if (pitfalls.has(Pitfall::lambda_b1)) {
      transpose_multiply_text_slip(rows, mlcp.body_count(), lambda, a_of_body);
    } else {
      transpose_multiply(rows, mlcp.body_count(), lambda, a_of_body);
    }
    const bool clamp_increment = pitfalls.has(Pitfall::clamp_increment);
    for (int iter = 0; iter < settings.iterations; ++iter) {
      if (clamp_increment) {
        sweep<N, true>(rows, a_of_body, lambda);
      } else {
        sweep<N, false>(rows, a_of_body, lambda);
      }
      result.iterations = iter + 1;
      if (!measure) continue;
      const double r = mlcp.residual(lambda);
      if (settings.record_sweeps) {
        result.residuals.push_back(r);
        result.lambdas.push_back(Eigen::Map<const Eigen::VectorXd>(lambda, mlcp.row_count()));
      }
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
