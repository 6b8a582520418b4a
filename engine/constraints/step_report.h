// What one constrained step solved, for a tutorial's step-through output and for tests.
//
//   rows   J in sparse form (Jsp, Jmap), ζ and the bounds λ⁻, λ⁺   (eq. 3-15, 3-24)
//   η, d   the MLCP's right-hand side and the diagonal of J B     (eq. 3-16)
//   λ_exp  the guess PGS started from (last step's λ, or 0)
//   λ      the answer, and ‖W‖ after every PGS sweep               (eq. 3-23, 3-24)
//   W      J B λ − η for the answer                                 (eq. 3-23)
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "constraints/mlcp.h"
#include "constraints/pgs_solver.h"

namespace lamina {

struct StepReport {
  Mlcp mlcp;                   // the rows with Bsp, η and d, as assembled at t
  Eigen::VectorXd lambda_exp;  // λ_exp, the warm start, in N or N·m
  PgsResult solution;          // λ, sweeps run, the residual after each sweep
  Eigen::VectorXd W;           // W = J B λ − η for the answer, in m/s² or rad/s² (eq. 3-23)
};

// The report as text: the dense J, Bᵀ and J B, then per row ζ, η, bounds, λ_exp, λ and W, then the
// residual after each sweep. Small systems only (J is printed in full, s × 6n).
std::string format_step_report(const StepReport& report);

}  // namespace lamina
