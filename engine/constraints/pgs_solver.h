// Projected Gauss-Seidel for the MLCP of eq. 3-24 (chapter 3, "Projected Gauss-Seidel Method").
#pragma once

#include <vector>

#include <Eigen/Core>

#include "constraints/mlcp.h"

namespace lamina {

struct PgsSettings {
  int iterations = 10;            // MAX_ITERATION of the text: sweeps over all rows
  double tolerance = 0.0;         // stop early once the MLCP residual is ≤ this; 0 runs every sweep
  bool record_residuals = false;  // keep the residual after every sweep (for plots and tests)
};

struct PgsResult {
  Eigen::VectorXd lambda;          // λ, in N (force) or N·m (torque); impulse is λ Δt
  int iterations = 0;              // sweeps run
  std::vector<double> residuals;   // the MLCP residual after each sweep, when recorded
};

// Runs sweep() up to settings.iterations times, counting them in result.iterations. After each
// sweep, when residuals are recorded or a tolerance is set, measures residual() (one double),
// records it if asked, and stops once it is ≤ a tolerance > 0. Recording alone never changes
// the sweeps run, so λ is the same bit for bit with or without it. Shared by Gauss-Seidel and PGS.
template <class Sweep, class Residual>
void run_sweeps(const PgsSettings& settings, Sweep&& sweep, Residual&& residual,
                PgsResult& result) {
  const bool measure = settings.record_residuals || settings.tolerance > 0.0;
  for (int iter = 0; iter < settings.iterations; ++iter) {
    sweep();
    result.iterations = iter + 1;
    if (!measure) continue;
    const double r = residual();
    if (settings.record_residuals) result.residuals.push_back(r);
    if (settings.tolerance > 0.0 && r <= settings.tolerance) break;
  }
}

// Solves J B λ = η within the rows' bounds, starting from the guess λ_exp (warm start).
// Follows the text's pseudo-code with its two faults mended: TransposeMultiply scales by λ[i]
// (the text writes λ[b1], λ[b2]), and a one-body row (Jmap[1] = −1) never reads a[−1].
// A friction row's bounds ±μ λc are read from its contact row's current λ (eq. 3-26).
PgsResult solve_pgs(const Mlcp& mlcp, const Eigen::VectorXd& lambda_exp, const PgsSettings& settings);

}  // namespace lamina
