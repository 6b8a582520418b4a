// Chapter 2 (unconstrained motion): one step of eq. 2-1..2-8, checked against closed forms of
// the discrete schemes, the analytic motion, and the invariants a planar scene must keep.
// Numbers printed with MESSAGE are the ones quoted in docs/ch2-unconstrained-motion.md.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinematics/inertia.h"
#include "kinematics/momentum.h"
#include "kinematics/quaternion.h"
#include "kinematics/wrench.h"
#include "motion/integrator.h"
#include "motion/rigid_body.h"

namespace {

using namespace lamina;

// Unit round-off of double.
constexpr double eps = std::numeric_limits<double>::epsilon();
const Vec3 gravity(0.0, -9.8, 0.0);  // the project's planar gravity (y up, as Box2D)

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Vec3 random_vec(std::mt19937& rng, double scale) {
  return Vec3(uniform(rng, -scale, scale), uniform(rng, -scale, scale),
              uniform(rng, -scale, scale));
}

Vec3 random_planar(std::mt19937& rng, double scale) {
  return Vec3(uniform(rng, -scale, scale), uniform(rng, -scale, scale), 0.0);
}

Quat random_rotation(std::mt19937& rng) {
  return Quat(Eigen::AngleAxisd(uniform(rng, -M_PI, M_PI), random_vec(rng, 1.0).normalized()));
}

// A dynamic 3D box (half extents 0.5, 0.2 and depth 1 m) at x with orientation q.
RigidBody box_3d(const Vec3& x, const Quat& q) {
  const double m = 2.0;
  return RigidBody::dynamic_body(m, box_inertia(m, 0.5, 0.2), x, q);
}

double kinetic_energy_of(const RigidBody& b) {
  return kinetic_energy(b.mass, b.v, b.inertia_world(), b.angular_velocity);
}

// Runs n steps of the chapter-2 world step for one body.
RigidBody fly(RigidBody body, const Vec3& g, double dt, int n, Integration scheme) {
  std::vector<RigidBody> bodies{body};
  for (int i = 0; i < n; ++i) step_unconstrained(bodies, g, dt, scheme);
  return bodies[0];
}

// Rotation angle of q1 relative to q0 about z, in (−π, π]: one step's increment, summed to
// follow a planar body's angle through any number of turns.
double angle_increment(const Quat& q0, const Quat& q1) { return planar_angle(q1 * q0.conjugate()); }

}  // namespace

TEST_SUITE("UnconstrainedMotion") {
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

  TEST_CASE("planar_angle inverts planar_orientation and wraps into (−π, π]") {
    std::mt19937 rng(203);
    for (int i = 0; i < 1000; ++i) {
      const double theta = uniform(rng, -M_PI, M_PI);
      // eq. 1-19 with d = z and back: a few ε of round-off in sin, cos and atan2.
      CHECK(std::abs(planar_angle(planar_orientation(theta)) - theta) <= 8.0 * eps);
      // q and −q are the same orientation; an angle one turn away is the same angle.
      const Quat q = planar_orientation(theta + 2.0 * M_PI * std::floor(uniform(rng, -3.0, 4.0)));
      const Quat minus_q(-q.w(), -q.x(), -q.y(), -q.z());
      CHECK(std::abs(planar_angle(q) - theta) <= 64.0 * eps);
      CHECK(std::abs(planar_angle(minus_q) - theta) <= 64.0 * eps);
    }
  }

  TEST_CASE("a force through the centre of mass gives no rotation") {
    std::mt19937 rng(204);
    const double dt = 1.0 / 60.0;
    for (int trial = 0; trial < 100; ++trial) {
      RigidBody body = box_3d(random_vec(rng, 10.0), random_rotation(rng));
      const Quat q0 = body.q;
      const Vec3 f = random_vec(rng, 50.0);
      body.apply_force_at(f, body.x);
      // eq. 1-33: (x − x) × F is exactly the zero vector.
      CHECK(body.torque == Vec3::Zero());
      integrate(body, dt);
      CHECK(body.angular_velocity == Vec3::Zero());
      // q only passes through the renormalisation, which may move its last bit.
      CHECK((body.q.coeffs() - q0.coeffs()).norm() <= 4.0 * eps);
      // eq. 2-3: v = m⁻¹ F Δt.
      CHECK((body.v - f * dt / body.mass).norm() <= 4.0 * eps * body.v.norm());
    }
  }

  TEST_CASE("an off-centre force gives the torque τ = r × F and ω = I⁻¹ τ Δt (eq. 1-33, 2-4)") {
    std::mt19937 rng(205);
    const double dt = 1.0 / 60.0;
    for (int trial = 0; trial < 100; ++trial) {
      RigidBody body = box_3d(random_vec(rng, 10.0), random_rotation(rng));
      const Vec3 r = random_vec(rng, 1.0), f = random_vec(rng, 50.0);
      body.apply_force_at(f, body.x + r);
      // (x + r) − x recovers r only to ε(|x| + |r|), hence the tolerance.
      CHECK((body.torque - r.cross(f)).norm() <= 4.0 * eps * (body.x.norm() + r.norm()) * f.norm());
      // The same accumulation as chapter 1's Wrench (eq. 1-31..1-33): identical arithmetic.
      Wrench wrench;
      wrench.add_at_point(f, body.x + r, body.x);
      CHECK(body.force == wrench.force);
      CHECK(body.torque == wrench.torque);
      // eq. 2-4 against an independent inverse: Eigen's inverse of R I0 Rᵀ (R from Eigen).
      const Mat3 rotation = body.q.toRotationMatrix();
      const Mat3 inertia = rotation * body.inertia_body * rotation.transpose();
      const Vec3 expected = inertia.inverse() * r.cross(f) * dt;
      integrate(body, dt);
      CHECK((body.angular_velocity - expected).norm() <= 1e-12 * expected.norm());
    }
    // Planar: a box of Box2D's inertia m (w² + h²)/12 pushed sideways at its corner.
    RigidBody box = box_body(1.0, 0.5, 0.25, Vec3::Zero());
    box.apply_force_at(Vec3(0.0, 10.0, 0.0), Vec3(0.5, 0.25, 0.0));  // τ_z = 0.5 × 10 = 5 N·m
    integrate(box, dt);
    const double box2d_inertia = box.mass * (1.0 * 1.0 + 0.5 * 0.5) / 12.0;
    CHECK(std::abs(box.angular_velocity.z() - 5.0 / box2d_inertia * dt) <=
          4.0 * eps * box.angular_velocity.z());
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

  TEST_CASE("box and disc bodies have Box2D's mass (density × area) and rotational inertia") {
    // Box2D 2.4 (b2PolygonShape/b2CircleShape::ComputeMass): a w × h box has m = ρ w h and
    // I = m (w² + h²)/12 about its centre; a disc m = ρ π r², I = m r²/2. Lamina's solids are
    // planar_depth = 1 m deep, so the same numbers hold with "area" read as volume.
    const double density = 3.0;
    const RigidBody box = box_body(density, 0.75, 0.25, Vec3::Zero());
    const double box_mass = density * 1.5 * 0.5;
    CHECK(std::abs(box.mass - box_mass) <= 4.0 * eps * box_mass);
    CHECK(std::abs(box.inertia_world()(2, 2) - box_mass * (1.5 * 1.5 + 0.5 * 0.5) / 12.0) <=
          8.0 * eps * box_mass);
    const RigidBody disc = disc_body(density, 0.4, Vec3::Zero());
    const double disc_mass = density * M_PI * 0.4 * 0.4;
    CHECK(std::abs(disc.mass - disc_mass) <= 4.0 * eps * disc_mass);
    CHECK(std::abs(disc.inertia_world()(2, 2) - 0.5 * disc_mass * 0.4 * 0.4) <=
          8.0 * eps * disc_mass);
    // The inverses agree with the inertia (eq. 5-1 needs them for every dynamic body).
    CHECK(std::abs(box.inverse_mass * box.mass - 1.0) <= 4.0 * eps);
    CHECK((box.inverse_inertia_world * box.inertia_world() - identity3()).cwiseAbs().maxCoeff() <=
          16.0 * eps);
  }

  TEST_CASE("bad input is rejected where a body is created, with a message") {
    const Mat3 inertia = box_inertia(1.0, 0.5, 0.5);
    const Vec3 origin = Vec3::Zero();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    using doctest::Contains;
    for (double mass : {-1.0, 0.0, nan, inf}) {
      CAPTURE(mass);
      CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(mass, inertia, origin),
                           Contains("mass must be finite and positive"), std::invalid_argument);
    }
    // The message carries the offending value.
    CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(-2.5, inertia, origin), Contains("got -2.5"),
                         std::invalid_argument);
    Mat3 skewed = inertia;
    skewed(0, 1) = 0.1;
    for (const Mat3& bad : {Mat3(Vec3(1.0, 1.0, -1.0).asDiagonal()), skewed, Mat3(nan * inertia)})
      CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(1.0, bad, origin), Contains("inertia tensor"),
                           std::invalid_argument);
    CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(1.0, inertia, Vec3(0.0, nan, 0.0)),
                         Contains("position is not finite"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(RigidBody::static_body(Vec3(inf, 0.0, 0.0)),
                         Contains("position is not finite"), std::invalid_argument);
    for (const Quat& q : {Quat(1.0, 1.0, 0.0, 0.0), Quat(0.0, 0.0, 0.0, 0.0),
                          Quat(nan, 0.0, 0.0, 0.0), Quat(1.0 + 1e-6, 0.0, 0.0, 0.0)}) {
      CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(1.0, inertia, origin, q),
                           Contains("not a unit quaternion"), std::invalid_argument);
      CHECK_THROWS_WITH_AS(RigidBody::static_body(origin, q), Contains("not a unit quaternion"),
                           std::invalid_argument);
    }
    for (double bad : {0.0, -1.0, nan, inf}) {
      CAPTURE(bad);
      CHECK_THROWS_WITH_AS(box_body(1.0, bad, 0.5, origin), Contains("half extents"),
                           std::invalid_argument);
      CHECK_THROWS_WITH_AS(box_body(1.0, 0.5, bad, origin), Contains("half extents"),
                           std::invalid_argument);
      CHECK_THROWS_WITH_AS(disc_body(1.0, bad, origin), Contains("radius"), std::invalid_argument);
      CHECK_THROWS_WITH_AS(box_body(bad, 0.5, 0.5, origin), Contains("density"),
                           std::invalid_argument);
      CHECK_THROWS_WITH_AS(disc_body(bad, 0.5, origin), Contains("density"), std::invalid_argument);
    }
    CHECK_THROWS_WITH_AS(box_body(1.0, 0.5, 0.5, Vec3(nan, 0.0, 0.0)),
                         Contains("position is not finite"), std::invalid_argument);
    // Good input passes, including a unit quaternion normalised by the caller.
    CHECK_NOTHROW(
        RigidBody::dynamic_body(1.0, inertia, origin, Quat(1.0, 2.0, 3.0, 4.0).normalized()));
  }

  TEST_CASE("a static body has zero inverse mass and inertia and never moves (eq. 5-1)") {
    std::mt19937 rng(207);
    const Vec3 x(1.0, -2.0, 0.0);
    const Quat q = planar_orientation(0.7);
    for (Integration scheme : {Integration::semi_implicit, Integration::explicit_euler}) {
      std::vector<RigidBody> bodies{RigidBody::static_body(x, q), box_body(1.0, 0.5, 0.5, x)};
      CHECK(bodies[0].is_static());
      CHECK_FALSE(bodies[1].is_static());
      CHECK(bodies[0].inverse_mass == 0.0);
      CHECK(bodies[0].inverse_inertia_body == Mat3::Zero());
      CHECK(bodies[0].inverse_inertia_world == Mat3::Zero());
      for (int i = 0; i < 100; ++i) {
        for (RigidBody& b : bodies)
          b.apply_force_at(random_vec(rng, 100.0), b.x + random_vec(rng, 1.0));
        step_unconstrained(bodies, gravity, 1.0 / 60.0, scheme);
      }
      // Exact: every change is a product with m⁻¹ = 0 or I⁻¹ = 0. q + 0 only passes through the
      // renormalisation, which may move its last bit.
      CHECK(bodies[0].x == x);
      CHECK(bodies[0].v == Vec3::Zero());
      CHECK(bodies[0].angular_velocity == Vec3::Zero());
      CHECK((bodies[0].q.coeffs() - q.coeffs()).norm() <= 4.0 * eps);
      // The dynamic body beside it, stepped by the same calls, did move.
      CHECK(bodies[1].x != x);
    }
  }

  TEST_CASE("the quaternion stays unit over 10⁴ steps of fast spin (eq. 2-6 alone would drift)") {
    // ω̂ q is orthogonal to q (Re(q* ω̂ q) = 0 for a pure ω̂), so the text's update q + ½ ω̂ q Δt
    // grows |q|² by exactly (1 + |ω|²Δt²/4) every step: |q_n| = (1 + |ω|²Δt²/4)^(n/2). The engine
    // renormalises after each step (DIGEST, "Where the seed is wrong", item 3).
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
