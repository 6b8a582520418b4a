// Gauss-Seidel for a dense equality system A λ = b (chapter 3, "Gauss-Seidel Method").
//
//   A        s × s, symmetric positive definite (J B of eq. 3-16 is, when J has full row rank)
//   b        s × 1, the right-hand side (η of eq. 3-16)
//   λ_exp    the guess the iterations start from
//   sweep:   for i = 0 .. s−1:  λ_i ← λ_i + (b_i − Σ_j A_ij λ_j) / A_ii
//   residual ‖A λ − b‖, which tends to 0 for positive definite A (the text cites Ren-Cang Li)
//
// Projected Gauss-Seidel (pgs_solver.h) is this sweep with each λ_i clamped to its bounds and
// A λ kept implicitly as a = B λ. This dense version is its independent reference: it shares
// no code with the solver it checks, only the settings and result types.
#pragma once

#include <Eigen/Core>

#include "constraints/sweep_settings.h"

namespace lamina {

// Solves A λ = b from λ_exp. settings.iterations caps the sweeps; settings.tolerance (if > 0)
// stops once ‖A λ − b‖ ≤ tolerance; record_sweeps keeps ‖A λ − b‖ (and λ) after every sweep.
SweepResult gauss_seidel(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                         const Eigen::VectorXd& lambda_exp, const SweepSettings& settings);

}  // namespace lamina
