// Joints and their limits (chapter 3, "Inequality constraint"): a joint-angle limit stops a
// falling rod and holds it, and every constraint refuses bad input where it is made. Planar
// scenes (x–y, y up).
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "constraints/angle_limit.h"
#include "constraints/constrained_step.h"
#include "constraints/distance_constraint.h"
#include "constraints/incline_constraint.h"
#include "constraints/jacobian_rows.h"
#include "constraints/revolute_joint.h"
#include "support/constraint_scenes.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, in m/s²

}  // namespace

TEST_SUITE("Joints") {
  TEST_CASE("a joint-angle limit stops a falling rod and then holds it with m g (L/2) cos θ_L") {
    // rod 1 m pinned at its end, released horizontal; it may not turn past θ_L = ∓45°. Mirrored
    // for the upper side: gravity up, the rod swings up to +45°.
    for (const LimitSide side : {LimitSide::lower, LimitSide::upper}) {
      const double s = side == LimitSide::lower ? 1.0 : -1.0;
      std::vector<RigidBody> bodies;
      ConstraintList constraints = pinned_rod(bodies, 0.0);
      constraints.push_back(std::make_unique<AngleLimit>(world, 0, -s * M_PI / 4.0, side));
      ConstrainedStepSettings settings;
      settings.step.gravity = Vec3(0.0, -s * g, 0.0);
      settings.step.iterations = 30;
      WarmStart warm_start;
      StepReport report;
      const auto C = [&] { return s * (planar_angle(bodies[0].q) + s * M_PI / 4.0); };
      for (int k = 0; k < 180; ++k) {
        const bool far = C() > 0.1;
        constrained_step(bodies, constraints, settings, warm_start, &report);
        // eq. 3-24 at λ⁻ = 0: a step that starts far from the limit gets no push from it
        if (far) CHECK(report.solution.lambda[2] == 0.0);
        // eq. 3-17: the limit holds to 1e-3 rad (PGS is stopped at 30 sweeps)
        CHECK(C() >= -1e-3);
      }
      // at rest on the limit: the limit's torque balances gravity's about the pin (statics)
      CHECK(std::abs(bodies[0].angular_velocity.z()) <= 1e-3);
      CHECK(relative_error(report.solution.lambda[2], bodies[0].mass * g * 0.5 * std::cos(M_PI / 4.0)) <= 1e-3);
      CHECK(std::abs(report.slack()[2]) <= 1e-3);
    }
  }

  TEST_CASE("constraints reject bad input with std::invalid_argument") {
    CHECK_THROWS_AS(InclineConstraint(0, Vec3::Zero(), Vec3(0.0, 2.0, 0.0)), std::invalid_argument);
    CHECK_THROWS_AS(InclineConstraint(-1, Vec3::Zero(), Vec3::UnitY()), std::invalid_argument);
    CHECK_THROWS_AS(DistanceConstraint(Anchor{0, Vec3::Zero()}, Anchor{0, Vec3::UnitX()}, 1.0),
                    std::invalid_argument);
    CHECK_THROWS_AS(DistanceConstraint(Anchor{world, Vec3::Zero()}, Anchor{0, Vec3::Zero()}, 0.0),
                    std::invalid_argument);
    CHECK_THROWS_AS(RevoluteJoint(Anchor{world, Vec3::Zero()}, Anchor{world, Vec3::UnitX()}),
                    std::invalid_argument);
    CHECK_THROWS_AS(AngleLimit(0, 1, 4.0, LimitSide::lower), std::invalid_argument);
    CHECK_THROWS_AS(AngleLimit(-2, 1, 0.0, LimitSide::upper), std::invalid_argument);
  }
}
