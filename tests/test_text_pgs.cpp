// The text's Projected Gauss-Seidel written line by line (constraints/text_pgs.h) against the
// engine's packed PgsSolver (pgs_solver.h) and the dense matrices of dense_system.h: the same
// MLCP (eq. 3-16, 3-24, 3-26), three independent codes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "constraints/dense_system.h"
#include "constraints/mlcp.h"
#include "constraints/pgs_solver.h"
#include "constraints/text_pgs.h"
#include "support/random_systems.h"

using namespace lamina;

namespace {

constexpr double dt = random_system_dt;  // Δt of every system here, in s

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// The largest |x_i − y_i|.
double largest_difference(const std::vector<double>& x, const Eigen::VectorXd& y) {
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    worst = std::max(worst, std::abs(x[i] - y[static_cast<Eigen::Index>(i)]));
  }
  return worst;
}

// Both codes do the same arithmetic in a different order: the text sums a 6-vector dot in
// Eigen's order, subtracts Jsp[i][0]·a[b1], then Jsp[i][1]·a[b2], and divides by d_i; the packed
// sweep sums [v_x v_y ω_z] (or all six) in index order, subtracts the two blocks' sum at once and
// multiplies by 1/d_i. So they are not the same bits: each λ update may differ by a few ulps of
// the largest λ, and 20 sweeps over ≤ 10 rows make at most 200 updates; were every difference
// to add up unabated, 200 × 4 ulps. The bound is 1000 ε max(1 N, max|λ|) (2.2e-13 relative;
// measured: 14 ε); a wrong index or sign moves λ by a fraction of λ itself.
constexpr double epsilon = std::numeric_limits<double>::epsilon();
constexpr double round_off = 1000.0 * epsilon;

}  // namespace

TEST_SUITE("TextPgs") {
  TEST_CASE("Convert, Multiply and TransposeMultiply are B = M⁻¹Jᵀ, J V and B λ written out") {
    std::mt19937 rng(41);
    for (Layout layout : {Layout::planar, Layout::general}) {
      const RandomSystem sys = random_mlcp_with_friction(rng, 4, 7, layout);
      const text::Problem p = text::make_problem(sys.bodies, sys.rows, dt);
      const auto s = static_cast<int>(sys.rows.size());
      const int n = static_cast<int>(sys.bodies.size());
      // expected: the dense M⁻¹ and J of dense_system.h (eq. 3-8, 3-12), by matrix products
      const Eigen::MatrixXd J = sys.dense.J;
      const Eigen::MatrixXd B_transpose = J * sys.dense.inverse_mass;
      const text::Blocks Bsp = text::Convert(p.Jsp, p.Jmap, p.M_inverse);
      std::vector<text::Vector6> V;
      std::vector<double> lambda;
      for (int b = 0; b < n; ++b) V.push_back(random_vec6(rng));
      for (int i = 0; i < s; ++i) lambda.push_back(uniform(rng, -20.0, 20.0));
      const std::vector<double> JV = text::Multiply(p.Jsp, p.Jmap, V);
      const std::vector<text::Vector6> a = text::TransposeMultiply(Bsp, p.Jmap, lambda, n);
      Eigen::VectorXd V_stacked(6 * n), lambda_stacked(s);
      for (int b = 0; b < n; ++b) V_stacked.segment<6>(6 * b) = V[static_cast<std::size_t>(b)];
      for (int i = 0; i < s; ++i) lambda_stacked[i] = lambda[static_cast<std::size_t>(i)];
      const Eigen::VectorXd JV_dense = J * V_stacked;
      const Eigen::VectorXd a_dense = B_transpose.transpose() * lambda_stacked;
      // entries of J, M⁻¹ ≤ 2, of V ≤ 1, λ ≤ 20: the sums are ≤ ~10², so 1e-12 is round-off
      for (int i = 0; i < s; ++i) {
        const auto& map = p.Jmap[static_cast<std::size_t>(i)];
        for (int k = 0; k < 2; ++k) {
          const Vec6 expected = map[k] < 0 ? Vec6::Zero()
                                           : Vec6(B_transpose.block<1, 6>(i, 6 * map[k]).transpose());
          CHECK((Bsp[static_cast<std::size_t>(i)][k] - expected).norm() <= 1e-12);
        }
        CHECK(std::abs(JV[static_cast<std::size_t>(i)] - JV_dense[i]) <= 1e-12);
        // η of eq. 3-16, the text's way (Multiply) against the dense reference's
        CHECK(std::abs(p.eta[static_cast<std::size_t>(i)] - sys.dense.eta[i]) <= 1e-9);
      }
      for (int b = 0; b < n; ++b) {
        CHECK((a[static_cast<std::size_t>(b)] - a_dense.segment<6>(6 * b)).norm() <= 1e-12);
      }
    }
  }

  TEST_CASE("the text's PGS gives the packed PGS's λ after every sweep, to round-off") {
    std::mt19937 rng(43);
    constexpr int sweeps = 20;
    double worst = 0.0;  // the largest |λ_text − λ_packed| seen, in units of ε max(1 N, |λ|)
    int identical = 0, compared = 0;
    for (Layout layout : {Layout::planar, Layout::general}) {
      for (int trial = 0; trial < 100; ++trial) {
        const int body_count = 2 + trial % 4, row_count = 2 + trial % 9;
        const RandomSystem sys = random_mlcp_with_friction(rng, body_count, row_count, layout);
        const text::Problem p = text::make_problem(sys.bodies, sys.rows, dt);
        // a warm start inside no particular bounds: the first sweep projects it
        std::vector<double> lambda_exp;
        for (int i = 0; i < row_count; ++i) lambda_exp.push_back(uniform(rng, -20.0, 20.0));
        text::Trace trace;
        text::ProjectedGaussSeidel(p, lambda_exp, sweeps, &trace);
        const Eigen::VectorXd start = Eigen::Map<const Eigen::VectorXd>(lambda_exp.data(), row_count);
        for (int k = 1; k <= sweeps; ++k) {
          const SweepResult packed = solve_pgs(sys.mlcp, start, {k, 0.0, false});
          const std::vector<double>& mine = trace.lambda_after_sweep[static_cast<std::size_t>(k - 1)];
          const double difference = largest_difference(mine, packed.lambda);
          const double scale = std::max(1.0, packed.lambda.cwiseAbs().maxCoeff());
          worst = std::max(worst, difference / (epsilon * scale));
          identical += difference == 0.0;
          ++compared;
          CHECK(difference <= round_off * scale);
        }
      }
    }
    MESSAGE("text PGS against packed PGS, 200 random MLCPs × 20 sweeps: largest |Δλ| = "
            << worst << " ε max|λ|; bit for bit equal in " << identical << " of " << compared);
  }
}
