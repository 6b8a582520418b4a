// How long an iterative solver sweeps, and what it reports: shared by Projected Gauss-Seidel
// (pgs_solver.h) and its dense reference, Gauss-Seidel (gauss_seidel.h), which each run their
// own loop over these settings.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace lamina {

struct SweepSettings {
  int iterations = 10;            // MAX_ITERATION of the text: sweeps over all rows
  double tolerance = 0.0;         // stop early once the residual is ≤ this; 0 runs every sweep
  bool record_sweeps = false;     // keep the residual and λ after every sweep (plots, tests, viewer)
};

struct SweepResult {
  Eigen::VectorXd lambda;          // λ, in N (force) or N·m (torque); impulse is λ Δt
  int iterations = 0;              // sweeps run
  std::vector<double> residuals;   // the residual after each sweep, when recorded
  std::vector<Eigen::VectorXd> lambdas;  // λ after each sweep, when recorded (PGS; the
                                         // chapter-6 methods keep their answer as one entry)
};

}  // namespace lamina
