// Chapter 2, the rotational half of a step: ω by eq. 2-4 with the gyroscopic term dropped
// (eq. 2-2), q by eq. 2-6 then renormalised. A torque-free spin's phase lag, |q| = 1 over many
// steps of fast spin, and what dropping L × ω costs off a principal axis.
// Numbers printed with MESSAGE are the ones quoted in docs/ch2-unconstrained-motion.md.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "kinematics/momentum.h"
#include "kinematics/quaternion.h"
#include "motion/integrator.h"
#include "motion/rigid_body.h"
#include "support/kinematics_support.h"
#include "support/motion_support.h"

using namespace lamina;
using namespace lamina::testing;

TEST_SUITE("AngularIntegration") {
  TEST_CASE("torque-free spin about z: ω and L constant, energy conserved, angle 2n·atan(ωΔt/2)") {
    // Without torque ω is never changed (eq. 2-4 adds exactly 0). The orientation update
    // (eq. 2-6) then normalisation turns the half-angle of q by atan(ωΔt/2) per step, not by
    // ωΔt/2: the angle after n steps is θ_n = 2n·atan(ωΔt/2) to round-off, which is ω t only up
    // to the scheme's phase lag ω³ t Δt²/12 (second order in Δt).
    const double omega = 3.0;  // rad/s
    double previous_lag = 0.0;
    for (int steps_per_second : {60, 120}) {
      const double dt = 1.0 / steps_per_second;
      const int n = 10 * steps_per_second;  // 10 s
      RigidBody body = box_body(1.5, 0.5, 0.25, Vec3(1.0, 2.0, 0.0), 0.4);
      body.angular_velocity = Vec3(0.0, 0.0, omega);
      const double theta0 = 0.4;
      const double energy0 = kinetic_energy_of(body);
      const Vec3 momentum0 = angular_momentum(body.inertia_world(), body.angular_velocity);
      double theta = theta0, energy_drift = 0.0, momentum_drift = 0.0;
      for (int i = 0; i < n; ++i) {
        const Quat before = body.q;
        integrate(body, dt);
        theta += angle_increment(before, body.q);
        energy_drift = std::max(energy_drift, std::abs(kinetic_energy_of(body) / energy0 - 1.0));
        momentum_drift = std::max(
            momentum_drift,
            (angular_momentum(body.inertia_world(), body.angular_velocity) - momentum0).norm() /
                momentum0.norm());
      }
      CHECK(body.angular_velocity == Vec3(0.0, 0.0, omega));  // exact: nothing is added to ω
      // eq. 1-47, 1-41: I_zz is invariant under rotation about z, so only round-off moves them.
      CHECK(energy_drift <= 1e-13);
      CHECK(momentum_drift <= 1e-13);
      // The discrete angle, to the round-off of n normalisations (≈ n ε).
      const double discrete = theta0 + 2.0 * n * std::atan(0.5 * omega * dt);
      CHECK((body.q.coeffs() - planar_orientation(discrete).coeffs()).norm() <= 4.0 * n * eps);
      CHECK(std::abs(theta - discrete) <= 4.0 * n * eps * std::abs(discrete));
      // Against the analytic angle ω t: the scheme's phase lag ω³ t Δt²/12, to its next term.
      const double t = n * dt;
      const double lag = theta0 + omega * t - theta;
      MESSAGE("spin ω = 3 rad/s, Δt = 1/" << steps_per_second << " s, t = 10 s: ωt − θ = " << lag
                                          << " rad");
      CHECK(std::abs(lag / (std::pow(omega, 3) * t * dt * dt / 12.0) - 1.0) <= 1e-3);
      if (previous_lag > 0.0) CHECK(std::abs(previous_lag / lag - 4.0) <= 1e-2);  // second order
      previous_lag = lag;
    }
  }

  TEST_CASE("the quaternion stays unit over 10⁴ steps of fast spin (eq. 2-6 alone would drift)") {
    // ω̂ q is orthogonal to q (Re(q* ω̂ q) = 0 for a pure ω̂), so the text's update q + ½ ω̂ q Δt
    // grows |q|² by exactly (1 + |ω|²Δt²/4) every step: |q_n| = (1 + |ω|²Δt²/4)^(n/2). The engine
    // renormalises after each step (docs/the-text.md, "Where the text is wrong or silent").
    std::mt19937 rng(208);
    const double dt = 1.0 / 240.0;
    const int n = 10000;
    RigidBody body = box_3d(Vec3::Zero(), random_rotation(rng));
    body.angular_velocity = Vec3(8.0, -12.0, 14.0);  // |ω| ≈ 20 rad/s about a tilted axis
    Quat raw = body.q;
    double norm_error = 0.0;
    for (int i = 0; i < n; ++i) {
      integrate(body, dt);
      norm_error = std::max(norm_error, std::abs(body.q.norm() - 1.0));
      const Quat q_dot = quaternion_derivative(body.angular_velocity, raw);  // eq. 1-29
      raw = Quat(raw.coeffs() + q_dot.coeffs() * dt);  // eq. 2-6, no normalisation
    }
    CHECK(norm_error <= 1e-12);
    // R stays a rotation.
    CHECK((body.rotation.transpose() * body.rotation - identity3()).cwiseAbs().maxCoeff() <= 1e-12);
    // The unnormalised update drifts exactly as predicted (round-off of n steps, ≈ n ε ≈ 2e-12).
    const double growth =
        std::pow(1.0 + body.angular_velocity.squaredNorm() * dt * dt / 4.0, 0.5 * n);
    MESSAGE("fast spin |ω| = " << body.angular_velocity.norm() << " rad/s, Δt = 1/240 s, " << n
                               << " steps: |q| without normalisation = " << raw.norm());
    CHECK(std::abs(raw.norm() / growth - 1.0) <= 1e-11);
    CHECK(raw.norm() > 2.0);
  }

  TEST_CASE(
      "the dropped gyroscopic term: off a principal axis ω stays constant and L = I ω does "
      "not (the limit of eq. 2-2)") {
    // A real torque-free body keeps L and lets ω wander (eq. 1-46 with τ = 0: ω̇ = I⁻¹ (L × ω)).
    // Eq. 2-2 drops L × ω, so the engine keeps ω instead. Planar bodies spin about z, a principal
    // axis of every Lamina shape, where L × ω = 0 and nothing is lost.
    RigidBody body = box_3d(Vec3::Zero(), Quat::Identity());
    body.angular_velocity = Vec3(1.0, 1.0, 1.0);
    const Vec3 momentum0 = angular_momentum(body.inertia_world(), body.angular_velocity);
    // The term the engine drops is not zero here.
    CHECK(angular_acceleration(body.inertia_world(), body.angular_velocity, Vec3::Zero()).norm() >
          0.1);
    for (int i = 0; i < 60; ++i) integrate(body, 1.0 / 60.0);
    CHECK(body.angular_velocity == Vec3(1.0, 1.0, 1.0));
    const double drift =
        (angular_momentum(body.inertia_world(), body.angular_velocity) - momentum0).norm() /
        momentum0.norm();
    MESSAGE("ω = (1, 1, 1) rad/s on a 1 × 0.4 × 1 m box, 1 s: |ΔL|/|L| = " << drift);
    CHECK(drift > 0.01);
  }

}  // TEST_SUITE
