// What one constrained step solved, for explanations, frames and tests: the step's assembled
// MLCP (a copy of the one the step solved), where PGS started and where it ended. Everything
// else — J, ζ, η, d, the bounds, W = J B λ − η, F_c = Jᵀ λ — is read from the MLCP's views.
#pragma once

#include <Eigen/Core>

#include "constraints/mlcp.h"
#include "constraints/sweep_settings.h"

namespace lamina {

struct StepReport {
  Mlcp mlcp;                   // the MLCP as assembled at t (eq. 3-16)
  Eigen::VectorXd lambda_exp;  // λ_exp, the warm start, in N or N·m
  SweepResult solution;        // λ, sweeps run, the residual ‖W‖ after each sweep (eq. 3-23, 3-24)

  // W = J B λ − η for the answer, in m/s² or rad/s² (eq. 3-23).
  Eigen::VectorXd slack() const { return mlcp.slack(solution.lambda.data()); }
  // Body b's share of F_c = Jᵀ λ, [f_c; τ_c] about its centre, in N and N·m (eq. 3-11, 5-9).
  Vec6 constraint_wrench(int body) const { return mlcp.constraint_wrench(body, solution.lambda.data()); }
};

}  // namespace lamina
