// Pendulums in motion (chapter 3): a bob on a distance constraint and a rod on a revolute joint
// swing with their analytic periods, and the rod's drift with and without the bias of eq. 3-14,
// on planar scenes (x–y, y up).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "constraints/constrained_step.h"
#include "constraints/distance_constraint.h"
#include "constraints/jacobian_rows.h"
#include "support/constraint_scenes.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, in m/s²

// The largest |component| that a planar scene must keep at exactly zero: z of x and v, x and y
// of ω, and x and y of q (a rotation about z only).
double out_of_plane(const RigidBody& body) {
  return std::max({std::abs(body.x.z()), std::abs(body.v.z()), std::abs(body.angular_velocity.x()),
                   std::abs(body.angular_velocity.y()), std::abs(body.q.x()), std::abs(body.q.y())});
}

// What a run of steps recorded for body 0.
struct Trace {
  std::vector<double> x;      // body 0's x after each step, in m
  std::vector<double> C;      // constraint error |x − pivot| − L after each step, in m
  double max_speed = 0.0;     // largest |v| of body 0, in m/s
  double out_of_plane = 0.0;  // largest out_of_plane(body 0) seen
};

// Steps the scene and records body 0, taking C as its distance from the origin minus length.
Trace run(std::vector<RigidBody>& bodies, const ConstraintList& constraints,
          const ConstrainedStepSettings& settings, int steps, double length) {
  Trace trace;
  WarmStart warm_start;
  for (int k = 0; k < steps; ++k) {
    constrained_step(bodies, constraints, settings, warm_start);
    trace.x.push_back(bodies[0].x.x());
    trace.C.push_back(bodies[0].x.norm() - length);
    trace.max_speed = std::max(trace.max_speed, bodies[0].v.norm());
    trace.out_of_plane = std::max(trace.out_of_plane, out_of_plane(bodies[0]));
  }
  return trace;
}

// The mean time between upward zero crossings of x, each crossing time interpolated linearly.
double measured_period(const std::vector<double>& x, double dt) {
  std::vector<double> crossings;
  for (size_t k = 1; k < x.size(); ++k) {
    if (x[k - 1] < 0.0 && x[k] >= 0.0) crossings.push_back(dt * (k - x[k] / (x[k] - x[k - 1])));
  }
  REQUIRE(crossings.size() >= 3);
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

// A disc of radius 5 cm (a near point mass) at angle θ0 from hanging straight down, L from the
// origin, held there by a distance constraint from the world origin to its centre.
ConstraintList simple_pendulum(std::vector<RigidBody>& bodies, double length, double theta0) {
  bodies.push_back(disc_body(100.0, 0.05, length * Vec3(std::sin(theta0), -std::cos(theta0), 0.0)));
  ConstraintList constraints;
  constraints.push_back(std::make_unique<DistanceConstraint>(Anchor{world, Vec3::Zero()},
                                                             Anchor{0, Vec3::Zero()}, length));
  return constraints;
}

}  // namespace

TEST_SUITE("Pendulum") {
  TEST_CASE("a simple pendulum swings with period 2π√(L/g) and stays in the plane") {
    // L = 1 m, θ0 = 0.05 rad (the amplitude adds θ0²/16 = 0.016 % to the period), Δt = 1/240 s
    std::vector<RigidBody> bodies;
    const ConstraintList rod = simple_pendulum(bodies, 1.0, 0.05);
    ConstrainedStepSettings settings;
    settings.step.dt = 1.0 / 240.0;
    const Trace trace = run(bodies, rod, settings, 2400, 1.0);
    const double period = measured_period(trace.x, settings.step.dt);
    MESSAGE("simple pendulum: period " << period << " s, 2π√(L/g) = " << 2.0 * M_PI * std::sqrt(1.0 / g) << " s");
    // analytic small-angle period, within 1 %
    CHECK(relative_error(period, 2.0 * M_PI * std::sqrt(1.0 / g)) <= 0.01);
    // planar scene: every out-of-plane component stays exactly zero
    CHECK(trace.out_of_plane == 0.0);
  }

  TEST_CASE("a rod on a revolute joint swings with period 2π√(I_pivot / (m g d))") {
    // rod 1 m long pinned at its end, d = 0.5 m from pivot to centre, θ0 = 0.05 rad, Δt = 1/240 s
    std::vector<RigidBody> bodies;
    const ConstraintList pin = pinned_rod(bodies, -M_PI / 2.0 + 0.05);
    ConstrainedStepSettings settings;
    settings.step.dt = 1.0 / 240.0;
    const RigidBody& rod = bodies[0];
    const double I_pivot = rod.inertia_body(2, 2) + rod.mass * 0.25;  // parallel axes
    const double expected = 2.0 * M_PI * std::sqrt(I_pivot / (rod.mass * g * 0.5));
    const Trace trace = run(bodies, pin, settings, 2400, 0.5);
    const double period = measured_period(trace.x, settings.step.dt);
    MESSAGE("pinned rod: period " << period << " s, 2π√(I_pivot/(m g d)) = " << expected << " s");
    // analytic physical-pendulum period (about 2π√(2L/3g) for a thin rod), within 1 %
    CHECK(relative_error(period, expected) <= 0.01);
    CHECK(trace.out_of_plane == 0.0);
  }

  TEST_CASE("pendulum drift: grows without bias, bounded by Δt² v² / (2 L β) with it") {
    // L = 1 m, θ0 = 1 rad, Δt = 1/60 s, 10 s. With the row solved exactly, one step moves the
    // bob from distance L + C to √((L + (1 − β) C)² + Δt² v_t²) (v_t ⟂ the rod), so
    //   β = 0:  C never decreases, and grows by ~Δt² v_t² / (2L) every step;
    //   β > 0:  C_{k+1} ≤ (1 − β) C_k + Δt² v²/(2L), hence 0 ≤ C ≤ Δt² v_max² / (2 L β).
    ConstrainedStepSettings settings;
    std::vector<RigidBody> loose;
    settings.step.beta = 0.0;
    const Trace drift = run(loose, simple_pendulum(loose, 1.0, 1.0), settings, 600, 1.0);
    for (size_t k = 1; k < drift.C.size(); ++k) CHECK(drift.C[k] >= drift.C[k - 1] - 1e-12);
    // it keeps growing: after 10 s more than three times its value after 2.5 s
    CHECK(drift.C.back() > 3.0 * drift.C[149]);
    std::vector<RigidBody> held;
    settings.step.beta = 0.2;
    const Trace bias = run(held, simple_pendulum(held, 1.0, 1.0), settings, 600, 1.0);
    const double bound = settings.step.dt * settings.step.dt * bias.max_speed * bias.max_speed / (2.0 * settings.step.beta);
    const auto [low, high] = std::minmax_element(bias.C.begin(), bias.C.end());
    CHECK(*low >= -1e-12);
    CHECK(*high <= bound);
    MESSAGE("drift after 10 s: β = 0: " << drift.C.back() << " m; β = 0.2: max " << *high
                                       << " m, bound " << bound << " m");
    CHECK(drift.C.back() > *high);
  }
}
