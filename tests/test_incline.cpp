// Fig 3-1 in motion: a body held on an incline by one equality row (chapter 3, eq. 3-1..3-4,
// 3-14, 3-16), and Fig 3-2: a body that may leave it, one inequality row (eq. 3-17..3-22), on
// planar scenes (x–y, y up).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "constraints/constrained_step.h"
#include "constraints/incline_constraint.h"
#include "constraints/jacobian_rows.h"
#include "support/constraint_scenes.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, in m/s²

}  // namespace

TEST_SUITE("Incline") {
  TEST_CASE("Fig 3-1: a body on an incline slides with g sin θ, held by m g cos θ") {
    for (double degrees : {10.0, 30.0, 45.0, 60.0}) {
      const double theta = degrees * M_PI / 180.0;
      const Vec3 N(std::sin(theta), std::cos(theta), 0.0);          // the incline's normal
      const Vec3 downhill(std::cos(theta), -std::sin(theta), 0.0);  // along the slope, down
      const Vec3 p(0.0, 1.0, 0.0);
      std::vector<RigidBody> bodies{box_body(4.0, 0.5, 0.25, p)};  // m = 2 kg
      ConstraintList constraints;
      constraints.push_back(std::make_unique<InclineConstraint>(0, p, N));
      const ConstrainedStepSettings settings;
      WarmStart warm_start;
      for (int k = 0; k < 30; ++k) {
        const double before = bodies[0].v.dot(downhill);
        StepReport report;
        constrained_step(bodies, constraints, settings, warm_start, &report);
        // analytic: a = g sin θ along the slope (g·downhill), and λ = m g cos θ (−m g·N);
        // one row is solved exactly by the first sweep, so 1e-9 relative is rounding only
        CHECK(relative_error((bodies[0].v.dot(downhill) - before) / settings.step.dt, g * std::sin(theta)) <= 1e-9);
        CHECK(relative_error(report.solution.lambda[0], 2.0 * g * std::cos(theta)) <= 1e-9);
        // eq. 3-1: the body stays on the line (C stays at rounding level, 1e-12 m)
        CHECK(std::abs((bodies[0].x - p).dot(N)) <= 1e-12);
      }
    }
  }

  TEST_CASE("Fig 3-1 as the solver sees it: J, ζ, η, bounds, λ, W for a 30° incline") {
    // m = 2 kg at rest, ε = 1 cm off the incline's line, β = 0.2, Δt = 1/60 s, g = (0, −9.8, 0)
    const double theta = M_PI / 6.0;
    const Vec3 N(std::sin(theta), std::cos(theta), 0.0);
    const Vec3 p(0.0, 1.0, 0.0);
    const double epsilon = 0.01;
    std::vector<RigidBody> bodies{box_body(4.0, 0.5, 0.25, p + epsilon * N)};
    ConstraintList constraints;
    constraints.push_back(std::make_unique<InclineConstraint>(0, p, N));
    const ConstrainedStepSettings settings;  // Δt = 1/60 s, β = 0.2
    WarmStart warm_start;
    StepReport report;
    constrained_step(bodies, constraints, settings, warm_start, &report);
    const Mlcp& mlcp = report.mlcp;
    const double lambda = report.solution.lambda[0];
    MESSAGE("Fig 3-1, θ = 30°, m = 2 kg, ε = 0.01 m, β = 0.2, Δt = 1/60 s: ζ = "
            << mlcp.zeta(0) << " m/s, η = " << mlcp.eta(0) << " m/s², d = " << mlcp.d(0)
            << " 1/kg, λ = " << lambda << " N, W = " << report.slack()[0] << " m/s²");
    // J = [Nᵀ 0ᵀ] (text, Fig 3-1 applied); one-body row against the world
    CHECK((mlcp.jacobian(0, 0).head<3>() - N).norm() == 0.0);
    CHECK(mlcp.jacobian(0, 0).tail<3>().norm() == 0.0);
    CHECK(mlcp.bodies_of(0)[1] == world);
    // eq. 3-14: ζ = −β ε / Δt = −0.12 m/s
    CHECK(mlcp.zeta(0) == doctest::Approx(-0.2 * epsilon * 60.0).epsilon(1e-12));
    // incline_constraint.h: an equality row, bounds (−∞, ∞), exactly
    CHECK(mlcp.bounds(0, &lambda) == std::array<double, 2>{-infinity, infinity});
    // eq. 3-16 with V = 0: η = ζ/Δt − N·g = −7.2 + 9.8 cos 30° m/s²
    const double eta = -7.2 + g * std::cos(theta);
    CHECK(mlcp.eta(0) == doctest::Approx(eta).epsilon(1e-12));
    // d = J M⁻¹ Jᵀ = 1/m; λ = η / d = m η
    CHECK(mlcp.d(0) == doctest::Approx(0.5).epsilon(1e-12));
    CHECK(lambda == doctest::Approx(2.0 * eta).epsilon(1e-12));
    CHECK(std::abs(report.slack()[0]) <= 1e-12);
    // after the step ε is (1 − β) ε (eq. 3-14 with Δt written out, constraint.h)
    CHECK((bodies[0].x - p).dot(N) == doctest::Approx(0.8 * epsilon).epsilon(1e-9));
  }

  TEST_CASE("Fig 3-2: a box thrown off a one-sided incline flies free, lands on it and slides") {
    // m = 2 kg on a 30° line, thrown at 3 m/s along N and 1 m/s down the slope; Δt = 1/60 s
    const double theta = M_PI / 6.0;
    const Vec3 N(std::sin(theta), std::cos(theta), 0.0);
    const Vec3 downhill(std::cos(theta), -std::sin(theta), 0.0);
    const Vec3 p(0.0, 1.0, 0.0);
    std::vector<RigidBody> bodies{box_body(4.0, 0.5, 0.25, p)};
    bodies[0].v = 3.0 * N + downhill;
    ConstraintList constraints;
    constraints.push_back(std::make_unique<InclineConstraint>(0, p, N, InclineKind::one_sided));
    const ConstrainedStepSettings settings;
    WarmStart warm_start;
    // free flight under eq. 2-3, 2-5: after k steps v·N = 3 − k g cos θ Δt and
    // C = Δt (3k − g cos θ Δt k(k+1)/2), which would turn negative once k + 1 > 6/(g cos θ Δt)
    // = 42.4: step 41 is the first the line must act in
    const int landing = static_cast<int>(std::floor(6.0 / (g * std::cos(theta) * settings.step.dt))) - 1;
    for (int k = 0; k < 90; ++k) {
      StepReport report;
      constrained_step(bodies, constraints, settings, warm_start, &report);
      const double lambda = report.solution.lambda[0], W = report.slack()[0];
      CHECK(report.mlcp.bounds(0, &lambda) == std::array<double, 2>{0.0, infinity});
      // eq. 3-21: λ ≥ 0, W ≥ 0, λ W = 0. One row is solved exactly in one sweep, so W is
      // round-off: ≤ 1e-9 m/s² against terms up to 200 m/s² (in flight W = (v(t+Δt)·N + C/Δt)/Δt
      // reaches 180 m/s²)
      CHECK(lambda >= 0.0);
      CHECK(W >= -1e-9);
      CHECK(std::min(lambda, W) <= 1e-9);
      // eq. 3-17: never below the line (C ≥ 0 to 1e-12 m, rounding)
      CHECK((bodies[0].x - p).dot(N) >= -1e-12);
      if (k < landing) {
        CHECK(lambda == 0.0);  // in the air the line does not pull (eq. 3-21: λ = 0, W > 0)
        CHECK(W > 0.0);
      } else if (k <= landing + 1) {
        // the landing takes two steps: the first lets the gap close exactly (ζ = −C/Δt,
        // eq. 3-18), the second, from C = 0, stops what is left of the approach (ζ = 0, eq. 3-19)
        CHECK(lambda > 2.0 * g * std::cos(theta));
        MESSAGE("Fig 3-2: landing, step " << k << ": λ = " << lambda << " N");
      } else {
        // on the line: λ = m g cos θ (analytic, as Fig 3-1) and the box slides
        CHECK(relative_error(lambda, 2.0 * g * std::cos(theta)) <= 1e-9);
      }
    }
  }
}
