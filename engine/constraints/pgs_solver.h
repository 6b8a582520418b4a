// Projected Gauss-Seidel for the MLCP of eq. 3-24 (chapter 3, "Projected Gauss-Seidel Method").
//
//   start    a = B λ_exp                        (the text's TransposeMultiply)
//   sweep    for each row i:
//              Δ = (η_i − J_i · a) / d_i        (Gauss-Seidel's (b_i − Σ_j A_ij λ_j) / A_ii)
//              λ_i ← clamp(λ_i + Δ, λ⁻_i, λ⁺_i)  (friction rows: ±μ λc of their contact row's
//                                                current λ, eq. 3-26)
//              a ← a + (λ_i new − old) B_i
// The text's pseudo-code with its two faults mended: TransposeMultiply scales by λ[i] (the text
// writes λ[b1], λ[b2]), and a one-body row (Jmap[1] = −1) never reads a[−1].
#pragma once

#include <vector>

#include "constraints/mlcp.h"
#include "constraints/sweep_settings.h"

namespace lamina {

// PGS's working memory, a = B λ per body, kept from solve to solve so that a World step
// allocates nothing once its buffers have grown.
class PgsSolver {
 public:
  // Up to settings.iterations sweeps on λ in place (λ holds λ_exp on entry). After each sweep,
  // when residuals are recorded or a tolerance is set, measures mlcp.residual(λ), records it if
  // asked and stops once it is ≤ a tolerance > 0. Recording alone never changes the sweeps run,
  // so λ is the same bit for bit with or without it. result.iterations and result.residuals are
  // filled; result.lambda is left alone.
  void solve(const Mlcp& mlcp, double* lambda, const SweepSettings& settings, SweepResult& result);

  // (B λ)_b after the last sweep of the last solve: body b's velocity change per Δt from the
  // rows, [v; ω].
  Vec6 velocity_change(int body) const;

 private:
  template <int N>
  std::vector<Block<N>>& a();

  bool planar_ = true;                 // the layout of the last solve
  std::vector<Block<3>> planar_a_;     // a in the planar layout
  std::vector<Block<6>> general_a_;    // a in the general layout
};

// Solves the MLCP from the guess λ_exp (warm start) in a solver of its own; a caller solving
// every step keeps a PgsSolver instead.
SweepResult solve_pgs(const Mlcp& mlcp, const Eigen::VectorXd& lambda_exp,
                      const SweepSettings& settings);

}  // namespace lamina
