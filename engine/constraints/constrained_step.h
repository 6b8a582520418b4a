// One step of constrained motion, t → t + Δt (chapter 3, "Equation of motion").
//
//   F_ext  = forces accumulated on the bodies + m g                   (eq. 3-9, 5-2)
//   rows   = every constraint's J, ζ, λ⁻, λ⁺ at t                      (eq. 3-8, 3-15, 3-24)
//   J B λ = η, λ⁻ ≤ λ ≤ λ⁺  solved by PGS from λ_exp                   (eq. 3-16, 3-24)
//   F_c    = Jᵀ λ, added to the accumulated force and torque           (eq. 3-11)
//   then the chapter-2 step under F_ext + F_c, and the forces cleared  (eq. 2-1..2-8)
// λ is a force: the impulse over the step is λ Δt.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "constraints/constraint.h"
#include "constraints/pgs_solver.h"
#include "constraints/step_report.h"
#include "constraints/step_settings.h"
#include "motion/integrator.h"

namespace lamina {

struct ConstrainedStepSettings {
  StepSettings step;                        // g, Δt, β and the PGS sweeps
  double tolerance = 0.0;                   // stop PGS once ‖W‖ ≤ this; 0 runs every sweep
  bool warm_start = true;                   // start PGS from last step's λ when the rows match
  Integration scheme = Integration::semi_implicit;  // eq. 2-5 or its explicit variant
};

// Last step's answer, kept between steps as the next PGS starting guess λ_exp.
struct WarmStart {
  std::vector<std::array<int, 2>> Jmap;  // last step's rows' body pairs, in row order
  Eigen::VectorXd lambda;                // last step's λ, in N or N·m

  // λ_exp for rows [first, last): last step's λ if the rows are on the same bodies in the same
  // order (the same constraints), else zeros, appended to `out` (a World step allocates nothing).
  void append_guess(const ConstraintRow* first, const ConstraintRow* last,
                    std::vector<double>& out) const;
  // Keeps rows [first, last)'s body pairs and their λ (solved[0 .. last − first)) for the next
  // step.
  void remember(const ConstraintRow* first, const ConstraintRow* last, const double* solved);
};

// Advances the bodies by one step under gravity, the forces already accumulated on them, and the
// constraints. warm_start carries λ from step to step. If report is given, it is filled with what
// was solved (and PGS records its residual after every sweep); without it nothing extra is done.
void constrained_step(std::vector<RigidBody>& bodies, const ConstraintList& constraints,
                      const ConstrainedStepSettings& settings, WarmStart& warm_start,
                      StepReport* report = nullptr);

}  // namespace lamina
