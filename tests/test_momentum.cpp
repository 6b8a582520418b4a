// Chapter 1, momentum and energy: P = m v, L = I ω and E against sums over the particles
// (eq. 1-38, 1-41, 1-47), and ω̇ = I⁻¹ (L × ω + τ) and the power F·v + τ·ω (eq. 1-46, 1-48)
// against finite differences of a rigid motion with a closed form. Each comparison states its
// tolerance and where the expected value comes from.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kinematics/inertia.h"
#include "kinematics/math_types.h"
#include "kinematics/momentum.h"
#include "kinematics/particle.h"
#include "support/kinematics_support.h"

using namespace lamina;
using namespace lamina::testing;

namespace {

double total_mass(const std::vector<PointMass>& points) {
  double m = 0.0;
  for (const PointMass& p : points) m += p.mass;
  return m;
}

}  // namespace

TEST_SUITE("Momentum") {
  TEST_CASE("L = I ω equals the sum of the particles' moments of momentum (eq. 1-30, 1-41)") {
    std::mt19937 rng(111);
    for (int i = 0; i < trials; ++i) {
      const std::vector<PointMass> points = random_points(rng, 12);
      const Vec3 x = centre_of_mass(points);
      const Mat3 inertia = point_set_inertia(points, x);
      const Vec3 v = random_vec(rng, 5.0);
      const Vec3 omega = random_vec(rng, 5.0);
      // Σ m_i r_i × v_i with v_i from eq. 1-30 = Σ m_i r_i × (ω × r_i), since Σ m_i r_i = 0.
      Vec3 sum = Vec3::Zero();
      double scale = 0.0;
      for (const PointMass& p : points) {
        const Vec3 r = p.position - x;
        sum += p.mass * r.cross(particle_velocity(v, omega, x, p.position));
        scale += p.mass * r.norm() * (v.norm() + omega.norm() * r.norm());
      }
      // Round-off: the cancelling Σ m_i r_i × v term leaves ~ε times the sum of term sizes.
      CHECK((angular_momentum(inertia, omega) - sum).norm() <= 32.0 * eps * scale);
    }
  }

  TEST_CASE("P = m v equals the sum of the particles' momenta (eq. 1-30, 1-38)") {
    std::mt19937 rng(112);
    for (int i = 0; i < trials; ++i) {
      const std::vector<PointMass> points = random_points(rng, 12);
      const Vec3 x = centre_of_mass(points);
      const Vec3 v = random_vec(rng, 5.0);
      const Vec3 omega = random_vec(rng, 5.0);
      Vec3 sum = Vec3::Zero();
      double scale = 0.0;
      for (const PointMass& p : points) {
        sum += p.mass * particle_velocity(v, omega, x, p.position);
        scale += p.mass * (v.norm() + omega.norm() * (p.position - x).norm());
      }
      // Round-off of a 12-term sum of vectors, relative to the sum of term sizes.
      CHECK((linear_momentum(total_mass(points), v) - sum).norm() <= 32.0 * eps * scale);
    }
  }

  TEST_CASE("kinetic energy equals the sum of the particles' ½ m_i |v_i|² (eq. 1-30, 1-47)") {
    std::mt19937 rng(113);
    for (int i = 0; i < trials; ++i) {
      const std::vector<PointMass> points = random_points(rng, 12);
      const Vec3 x = centre_of_mass(points);
      const Mat3 inertia = point_set_inertia(points, x);
      const Vec3 v = random_vec(rng, 5.0);
      const Vec3 omega = random_vec(rng, 5.0);
      double sum = 0.0;
      for (const PointMass& p : points)
        sum += 0.5 * p.mass * particle_velocity(v, omega, x, p.position).squaredNorm();
      // A 12-term sum of positive terms; the cross term m v·(ω × Σ m_i r_i) cancels. 64 ε.
      CHECK(std::abs(kinetic_energy(total_mass(points), v, inertia, omega) - sum) <=
            64.0 * eps * sum);
    }
  }

  TEST_CASE(
      "ω̇ = I⁻¹ (L × ω + τ) matches the motion when τ = dL/dt of L = I(t) ω(t) "
      "(eq. 1-37, 1-41, 1-43..1-46)") {
    std::mt19937 rng(115);
    const double h = 1e-4;
    for (int i = 0; i < trials; ++i) {
      const RigidMotion motion = RigidMotion::random(rng);
      const Mat3 inertia_body = point_set_inertia(random_points(rng, 8), Vec3::Zero());
      const double t = uniform(rng, -2.0, 2.0);
      const auto inertia = [&](double s) {
        return world_inertia(motion.rotation(s), inertia_body);
      };
      const auto momentum = [&](double s) { return angular_momentum(inertia(s), motion.omega(s)); };
      // eq. 1-43: the torque that produces this motion is τ = L̇, here by central difference.
      const Vec3 torque = central_difference(momentum, t, h);
      const Vec3 omega_dot = angular_acceleration(inertia(t), motion.omega(t), torque);
      // Expected: the motion's own ω̇, by central difference of ω(t) (independent of eq. 1-46).
      const auto omega = [&](double s) { return motion.omega(s); };
      const Vec3 expected = central_difference(omega, t, h);
      // Error budget: L''' ≤ 27 |I0| k⁴ (I(t) = R I0 Rᵀ has derivatives ≤ (2k)ʲ |I0|), so the
      // torque is off by ≤ √3 h²/6 · 27 |I0| k⁴ and ω̇ by |I⁻¹| times that; ω''' ≤ k⁴ adds
      // ≤ h²/3 k⁴.
      const Mat3 inverse = inertia(t).inverse();
      const double k4 = std::pow(motion.rate(), 4);
      const double tolerance = h * h * k4 * (8.0 * inverse.norm() * inertia_body.norm() + 1.0) +
                               1e4 * eps * inverse.norm() * momentum(t).norm() / h;
      CHECK((omega_dot - expected).norm() <= tolerance);
    }
  }

  TEST_CASE("power F·v + τ·ω is the rate of change of kinetic energy (eq. 1-47, 1-48)") {
    std::mt19937 rng(116);
    const double h = 1e-4;
    for (int i = 0; i < trials; ++i) {
      const RigidMotion motion = RigidMotion::random(rng);
      const double m = uniform(rng, 0.5, 3.0);
      const Mat3 inertia_body = point_set_inertia(random_points(rng, 8), Vec3::Zero());
      const double t = uniform(rng, -2.0, 2.0);
      const auto inertia = [&](double s) {
        return world_inertia(motion.rotation(s), inertia_body);
      };
      const auto energy = [&](double s) {
        return Eigen::Matrix<double, 1, 1>(
            kinetic_energy(m, motion.v(s), inertia(s), motion.omega(s)));
      };
      // The force and torque that drive this motion (Newton–Euler, written out independently of
      // eq. 1-46): F = m a, τ = L̇ = I ω̇ + ω × (I ω).
      const Vec3 omega = motion.omega(t);
      const Vec3 force = m * motion.a;
      const Vec3 torque = inertia(t) * motion.omega_dot(t) + omega.cross(inertia(t) * omega);
      const double expected = central_difference(energy, t, h)(0);
      // ½ m |v|² is quadratic in t (no truncation error); ½ ωᵀ I ω = ½ ω_bᵀ I0 ω_b with the
      // body-frame ω_b(t) = R0ᵀ R_B(t)ᵀ (Ω d1 + s d2) turning at rate |s|, so its third
      // derivative is ≤ 4 |I0| |s|³ k²: error ≤ h²/6 · 4 |I0| |s|³ k².
      const double tolerance = h * h / 6.0 * 4.0 * inertia_body.norm() *
                                   std::pow(std::abs(motion.spin), 3) * std::pow(motion.rate(), 2) +
                               1e3 * eps * energy(t)(0) / h;
      CHECK(std::abs(power(force, motion.v(t), torque, omega) - expected) <= tolerance);
    }
  }

}  // TEST_SUITE
