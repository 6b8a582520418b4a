// Chapter 2, the two integration schemes, semi-implicit (eq. 2-5) and explicit Euler: closed
// forms of the discrete free flight, first-order convergence to the parabola, kinetic energy
// against the work done, a spring, and planar bodies kept exactly planar.
// Numbers printed with MESSAGE are the ones quoted in docs/ch2-unconstrained-motion.md.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "motion/integrator.h"
#include "motion/rigid_body.h"
#include "support/kinematics_support.h"
#include "support/motion_support.h"

using namespace lamina;
using namespace lamina::testing;

namespace {

Vec3 random_planar(std::mt19937& rng, double scale) {
  return Vec3(uniform(rng, -scale, scale), uniform(rng, -scale, scale), 0.0);
}

// Runs n steps of the chapter-2 world step for one body.
RigidBody fly(RigidBody body, const Vec3& g, double dt, int n, Integration scheme) {
  std::vector<RigidBody> bodies{body};
  for (int i = 0; i < n; ++i) step_unconstrained(bodies, g, dt, scheme);
  return bodies[0];
}

}  // namespace

TEST_SUITE("Integrator") {
  TEST_CASE("free flight: semi-implicit position is x0 + v0 nΔt + g Δt² n(n+1)/2 (eq. 2-3, 2-5)") {
    // With v_k = v0 + k g Δt and x_{k+1} = x_k + v_{k+1} Δt (eq. 2-5), x_n = x0 + v0 nΔt +
    // g Δt² (1 + … + n). Round-off grows like n ε relative: 1e-12 holds for n = 600 (n ε ≈ 1e-13).
    std::mt19937 rng(201);
    const double dt = 1.0 / 60.0;
    const int n = 600;
    for (int trial = 0; trial < 20; ++trial) {
      RigidBody body = box_3d(random_vec(rng, 10.0), random_rotation(rng));
      body.v = random_vec(rng, 10.0);
      body.angular_velocity = random_vec(rng, 5.0);  // spinning changes nothing for x
      const Vec3 x0 = body.x, v0 = body.v;
      const RigidBody end = fly(body, gravity, dt, n, Integration::semi_implicit);
      const Vec3 expected = x0 + v0 * (n * dt) + gravity * (dt * dt * n * (n + 1) / 2.0);
      // Relative to the size of the terms, so that a closed form near 0 is not a problem.
      const double scale =
          x0.norm() + v0.norm() * n * dt + gravity.norm() * dt * dt * n * (n + 1) / 2.0;
      CHECK((end.x - expected).norm() <= 1e-12 * scale);
      // eq. 2-3: v_n = v0 + n g Δt, the same in both schemes.
      CHECK((end.v - (v0 + gravity * (n * dt))).norm() <=
            1e-12 * (v0.norm() + gravity.norm() * n * dt));
    }
  }

  TEST_CASE("free flight: explicit position is x0 + v0 nΔt + g Δt² n(n−1)/2") {
    // x_{k+1} = x_k + v_k Δt: the sum runs over 0 … n−1.
    std::mt19937 rng(202);
    const double dt = 1.0 / 60.0;
    const int n = 600;
    for (int trial = 0; trial < 20; ++trial) {
      RigidBody body = box_3d(random_vec(rng, 10.0), random_rotation(rng));
      body.v = random_vec(rng, 10.0);
      const Vec3 x0 = body.x, v0 = body.v;
      const RigidBody end = fly(body, gravity, dt, n, Integration::explicit_euler);
      const Vec3 expected = x0 + v0 * (n * dt) + gravity * (dt * dt * n * (n - 1) / 2.0);
      const double scale =
          x0.norm() + v0.norm() * n * dt + gravity.norm() * dt * dt * n * (n - 1) / 2.0;
      CHECK((end.x - expected).norm() <= 1e-12 * scale);
    }
  }

  TEST_CASE("free flight: both schemes converge to the parabola at first order in Δt") {
    // Analytic: x(T) = x0 + v0 T + ½ g T². From the closed forms above, with T = nΔt, the
    // semi-implicit error is +g T Δt/2 and the explicit one −g T Δt/2: halving Δt halves both.
    const double T = 2.0;
    const Vec3 x0(0.0, 10.0, 0.0), v0(3.0, 4.0, 0.0);
    const Vec3 parabola = x0 + v0 * T + 0.5 * gravity * T * T;
    for (Integration scheme : {Integration::semi_implicit, Integration::explicit_euler}) {
      const double sign = scheme == Integration::semi_implicit ? 1.0 : -1.0;
      const std::string name = scheme == Integration::semi_implicit ? "semi-implicit" : "explicit";
      double previous = 0.0;
      for (int n = 60; n <= 960; n *= 2) {
        const double dt = T / n;
        RigidBody body = box_3d(x0, Quat::Identity());
        body.v = v0;
        const Vec3 error = fly(body, gravity, dt, n, scheme).x - parabola;
        MESSAGE(name << " Δt = 1/" << n / T << " s: y error at T = 2 s " << error.y() << " m");
        // The closed form of the error, up to the round-off of n ≤ 960 steps on |x| ≈ 20 m
        // (≈ n ε |x| ≈ 4e-12 m, relative to the error ≥ 0.02 m: 1e-11 leaves a margin of ~4).
        CHECK((error - sign * gravity * (T * dt / 2.0)).norm() <= 1e-11 * gravity.norm() * T * dt);
        if (previous > 0.0) CHECK(std::abs(previous / error.norm() - 2.0) <= 1e-6);
        previous = error.norm();
      }
    }
  }

  TEST_CASE(
      "kinetic energy under a constant force and torque matches the work done, "
      "to first order in Δt (eq. 1-47, 1-48)") {
    // A planar box pushed by a constant force F at its centre and turned by a constant couple τ.
    // Work done along the simulated path: W = F·(x_n − x0) + τ_z (θ_n − θ0). With v_n = n a Δt
    // exact in both schemes, E_n = ½ (m a² + I α²) t² equals the integral of eq. 1-48 along the
    // analytic motion; the first-order error sits in the path: E_n − W = ∓½ (m a² + I α²) t Δt,
    // so (E_n − W)/W ≈ ∓Δt/t (semi-implicit −, explicit +).
    // Translation and rotation carry comparable energy (0.25 J and 0.1 J at T), and α is small
    // enough that the O(Δt²) phase error of the orientation update (see the spin test) stays
    // far below the first-order term.
    const Vec3 force(0.3, 0.4, 0.0);
    const Vec3 couple_force(0.0, 0.2, 0.0), couple_arm(0.5, 0.0, 0.0);  // τ_z = 2·0.5·0.2 = 0.2 N·m
    const double torque = 0.2;
    const double T = 2.0;
    for (Integration scheme : {Integration::semi_implicit, Integration::explicit_euler}) {
      const double sign = scheme == Integration::semi_implicit ? -1.0 : 1.0;
      const std::string name = scheme == Integration::semi_implicit ? "semi-implicit" : "explicit";
      double previous = 0.0;
      for (int n = 60; n <= 960; n *= 2) {
        const double dt = T / n;
        RigidBody body = box_body(1.0, 1.0, 0.5, Vec3::Zero());  // m = 2 kg, I_zz = 5/6 kg·m²
        const double alpha = torque / body.inertia_world()(2, 2);
        double theta = 0.0;
        for (int i = 0; i < n; ++i) {
          body.apply_force_at(force, body.x);
          body.apply_force_at(couple_force, body.x + couple_arm);
          body.apply_force_at(-couple_force, body.x - couple_arm);
          const Quat before = body.q;
          integrate(body, dt, scheme);
          body.clear_forces();
          theta += angle_increment(before, body.q);
        }
        const double energy = kinetic_energy_of(body);
        const double work = force.dot(body.x) + torque * theta;
        // eq. 1-48 integrated along the analytic motion: ∫ (F·a + τ α) t dt = ½ (F·a + τ α) T².
        const double analytic = 0.5 * (force.squaredNorm() / body.mass + torque * alpha) * T * T;
        CHECK(std::abs(energy / analytic - 1.0) <= 1e-12);
        const double relative = (energy - work) / work;
        MESSAGE(name << " Δt = 1/" << n / T << " s: (E − W)/W at T = 2 s = " << relative);
        // ∓Δt/T, up to the O(Δt²) of the rotation angle and the O(Δt²) of dividing by W.
        CHECK(std::abs(relative - sign * dt / T) <= 2.0 * (dt / T) * (dt / T));
        if (previous > 0.0) CHECK(std::abs(previous / std::abs(relative) - 2.0) <= 0.05);
        previous = std::abs(relative);
      }
    }
  }

  TEST_CASE(
      "a spring: explicit Euler gains energy by (1 + ω²Δt²) per step, semi-implicit "
      "keeps it bounded") {
    // The text prefers eq. 2-5 because it is "more stable". A disc on a spring F = −k (x − a),
    // natural frequency ω = √(k/m). Explicit: (x, v) → (x + vΔt, v − ω² x Δt) multiplies
    // E = ½ m v² + ½ k x² by exactly 1 + ω²Δt² each step. Semi-implicit (symplectic) Euler
    // conserves H̃ = E − ½ k Δt x·v exactly instead, and |k x·v| ≤ ω E, so E stays within about
    // ωΔt of its start.
    const double dt = 1.0 / 60.0;
    const int n = 600;  // 10 s, 10 periods
    const Vec3 anchor(0.0, 0.0, 0.0);
    for (Integration scheme : {Integration::semi_implicit, Integration::explicit_euler}) {
      RigidBody disc = disc_body(1.0, 0.3, Vec3(0.5, 0.0, 0.0));
      const double k = disc.mass * 4.0 * M_PI * M_PI;  // ω = 2π rad/s: a period of 1 s
      const double omega = 2.0 * M_PI;
      const auto energy = [&](const RigidBody& b) {
        return 0.5 * b.mass * b.v.squaredNorm() + 0.5 * k * (b.x - anchor).squaredNorm();
      };
      const double energy0 = energy(disc);
      double worst = 0.0;
      for (int i = 0; i < n; ++i) {
        disc.apply_force_at(-k * (disc.x - anchor), disc.x);
        integrate(disc, dt, scheme);
        disc.clear_forces();
        worst = std::max(worst, std::abs(energy(disc) / energy0 - 1.0));
      }
      const double ratio = energy(disc) / energy0;
      if (scheme == Integration::explicit_euler) {
        MESSAGE("spring, explicit, Δt = 1/60 s: E(10 s)/E(0) = " << ratio);
        CHECK(std::abs(ratio / std::pow(1.0 + omega * omega * dt * dt, n) - 1.0) <= 1e-10);
      } else {
        MESSAGE("spring, semi-implicit, Δt = 1/60 s: E(10 s)/E(0) = "
                << ratio << ", largest |E/E0 − 1| = " << worst);
        CHECK(worst <= omega * dt);
      }
    }
  }

  TEST_CASE("planar bodies stay planar: out-of-plane state is exactly 0.0 over 10⁵ random steps") {
    // No masking anywhere: with z = 0 in every input, every product that could leak out of the
    // plane multiplies an exact 0, so the out-of-plane components stay exactly 0.0 (not merely
    // small). |q| stays 1 to the round-off of one normalisation.
    std::mt19937 rng(206);
    const double dt = 1.0 / 60.0;
    const int steps = 100000;
    for (Integration scheme : {Integration::semi_implicit, Integration::explicit_euler}) {
      std::vector<RigidBody> bodies{box_body(2.0, 0.6, 0.4, Vec3(0.0, 5.0, 0.0), 0.3),
                                    disc_body(2.0, 0.5, Vec3(3.0, 5.0, 0.0), -1.0)};
      bodies[1].angular_velocity = Vec3(0.0, 0.0, 2.0);
      long leaks = 0;
      double norm_error = 0.0;
      for (int i = 0; i < steps; ++i) {
        for (RigidBody& b : bodies)
          b.apply_force_at(random_planar(rng, 5.0), b.x + random_planar(rng, 0.5));
        step_unconstrained(bodies, gravity, dt, scheme);
        for (const RigidBody& b : bodies) {
          if (b.x.z() != 0.0 || b.v.z() != 0.0 || b.angular_velocity.x() != 0.0 ||
              b.angular_velocity.y() != 0.0 || b.q.x() != 0.0 || b.q.y() != 0.0)
            ++leaks;
          norm_error = std::max(norm_error, std::abs(b.q.norm() - 1.0));
        }
      }
      CHECK(leaks == 0);
      for (const RigidBody& b : bodies) {
        CHECK(b.x.z() == 0.0);
        CHECK(b.v.z() == 0.0);
        CHECK(b.angular_velocity.x() == 0.0);
        CHECK(b.angular_velocity.y() == 0.0);
        CHECK(b.q.x() == 0.0);
        CHECK(b.q.y() == 0.0);
      }
      CHECK(norm_error <= 1e-12);
    }
  }

}  // TEST_SUITE
