#include "beyond/block_method.h"

#include <array>
#include <cmath>
#include <limits>

#include "beyond/island_solve.h"

namespace lamina {
namespace {

// Rows i and i + 1 are a two-point manifold's contact rows: one-sided, on the same bodies.
template <int N>
bool is_block(const PackedRow<N>& r1, const PackedRow<N>& r2) {
  auto one_sided = [](const PackedRow<N>& r) {
    return r.friction_of < 0 && r.lambda_min == 0.0 &&
           r.lambda_max == std::numeric_limits<double>::infinity();
  };
  return one_sided(r1) && one_sided(r2) && r1.map == r2.map;
}

// The 2 × 2 LCP of rows i, i + 1 solved exactly (the four cases of the header). Returns false,
// changing nothing, when the block is too near singular.
template <int N>
bool solve_block(const PackedRow<N>& r1, const PackedRow<N>& r2, std::size_t i, double* lambda,
                 Block<N>& a1, Block<N>& a2) {
  const bool two = r1.two_bodies();
  const double a11 = 1.0 / r1.inverse_d;
  const double a22 = 1.0 / r2.inverse_d;
  const double a12 = row_dot<N>(r1.J, r2.B[0], r2.B[1], two);  // J_1 · B_2 = J_2 · B_1
  const double det = a11 * a22 - a12 * a12;
  if (a11 * a11 >= 1000.0 * det) return false;  // Box2D's k_maxConditionNumber
  const std::array<double, 2> old = {lambda[i], lambda[i + 1]};
  // b = W − A λ_old: the pair's slack with its own λ taken out (eq. 3-23)
  const double b1 = row_dot<N>(r1.J, a1, a2, two) - r1.eta - (a11 * old[0] + a12 * old[1]);
  const double b2 = row_dot<N>(r2.J, a1, a2, two) - r2.eta - (a12 * old[0] + a22 * old[1]);
  std::array<double, 2> x{};
  const double both1 = (-b1 * a22 + b2 * a12) / det;
  const double both2 = (-b2 * a11 + b1 * a12) / det;
  if (both1 >= 0.0 && both2 >= 0.0) {
    x = {both1, both2};
  } else if (-b1 / a11 >= 0.0 && a12 * (-b1 / a11) + b2 >= 0.0) {
    x = {-b1 / a11, 0.0};
  } else if (-b2 / a22 >= 0.0 && a12 * (-b2 / a22) + b1 >= 0.0) {
    x = {0.0, -b2 / a22};
  } else if (b1 >= 0.0 && b2 >= 0.0) {
    x = {0.0, 0.0};
  } else {
    return false;  // round-off left no case: sweep the rows instead
  }
  lambda[i] = x[0];
  lambda[i + 1] = x[1];
  const double d1 = x[0] - old[0], d2 = x[1] - old[1];
  a1 += d1 * r1.B[0] + d2 * r2.B[0];
  if (two) a2 += d1 * r1.B[1] + d2 * r2.B[1];
  return true;
}

// One sweep: PGS's row update, with each manifold's contact rows taken as one block.
template <int N>
void block_sweep(const PackedRows<N>& rows, std::vector<Block<N>>& a, double* lambda) {
  for (std::size_t i = 0; i < rows.size();) {
    const int b1 = rows[i].map[0], b2 = rows[i].map[1];
    Block<N>& a1 = a[static_cast<std::size_t>(b1)];
    Block<N> none = Block<N>::Zero();
    Block<N>& a2 = b2 >= 0 ? a[static_cast<std::size_t>(b2)] : none;
    if (i + 1 < rows.size() && is_block(rows[i], rows[i + 1]) &&
        solve_block(rows[i], rows[i + 1], i, lambda, a1, a2)) {
      i += 2;
      continue;
    }
    pgs_row(rows[i], i, lambda, a1, a2);
    ++i;
  }
}

class BlockMethod final : public StepMethod {
 public:
  void take_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                 std::vector<double>& lambda, WorldReport* report) override {
    const Mlcp& mlcp = problem.velocity;
    std::function<void(int, const double*)> record;
    if (report != nullptr) {
      record = [&](int, const double* l) {
        report->velocity.solution.residuals.push_back(mlcp.residual(l));
        report->velocity.solution.lambdas.push_back(
            Eigen::Map<const Eigen::VectorXd>(l, mlcp.row_count()));
      };
    }
    block_sweeps(mlcp, lambda.data(), problem.settings.step.iterations, record);
    finish_step(problem, bodies, lambda, {}, split_, pgs_, report);
  }

 private:
  PgsSolver pgs_;       // the push-out's sweeps
  SplitImpulse split_;  // the position MLCP and the push-out
};

}  // namespace

void block_sweeps(const Mlcp& mlcp, double* lambda, int sweeps,
                  const std::function<void(int, const double*)>& after_sweep) {
  mlcp.visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    std::vector<Block<N>> a;
    // λ = λ_exp: a = B λ (the text's TransposeMultiply)
    transpose_multiply(rows, mlcp.body_count(), lambda, a);
    for (int sweep = 1; sweep <= sweeps; ++sweep) {
      block_sweep(rows, a, lambda);
      if (after_sweep) after_sweep(sweep, lambda);
    }
  });
}

std::unique_ptr<StepMethod> make_block_method() { return std::make_unique<BlockMethod>(); }

}  // namespace lamina
