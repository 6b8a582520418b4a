// Chapter 1, quaternions: the text's product and conjugate (eq. 1-17, 1-18), the rotation
// q v q* (eq. 1-20) and the time derivative ½ ω̂ q (eq. 1-29), checked against Eigen's quaternions
// and a finite difference over seeded random inputs. Each comparison states its tolerance and
// where the expected value comes from.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "kinematics/math_types.h"
#include "kinematics/quaternion.h"
#include "support/kinematics_support.h"

using namespace lamina;
using namespace lamina::testing;

TEST_SUITE("Quaternion") {
  TEST_CASE("the text's quaternion product and conjugate equal Eigen's (eq. 1-17, 1-18)") {
    std::mt19937 rng(105);
    for (int i = 0; i < trials; ++i) {
      // Not unit: the product formula holds for every quaternion.
      const Quat a(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3),
                   uniform(rng, -3, 3));
      const Quat b(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3),
                   uniform(rng, -3, 3));
      const Quat text = quaternion_product(a, b);
      const Quat eigen = a * b;
      // Each coefficient is a sum of four products: round-off ≤ 8 ε |a||b|.
      CHECK((text.coeffs() - eigen.coeffs()).norm() <= 8.0 * eps * a.norm() * b.norm());
      // The conjugate is exact (sign flips), and q q* = |q|² (a real number).
      CHECK(quaternion_conjugate(a).coeffs() == a.conjugate().coeffs());
      const Quat aa = quaternion_product(a, quaternion_conjugate(a));
      CHECK(std::abs(aa.w() - a.squaredNorm()) <= 8.0 * eps * a.squaredNorm());
      CHECK(aa.vec().norm() <= 8.0 * eps * a.squaredNorm());
    }
  }

  TEST_CASE("q v q* rotates v as R v does (eq. 1-20, 1-22)") {
    std::mt19937 rng(106);
    for (int i = 0; i < trials; ++i) {
      const Quat q = random_rotation(rng);
      const Vec3 v = random_vec(rng, 10.0);
      // Two quaternion products against one matrix product: round-off ≤ 32 ε |v|.
      CHECK((quaternion_rotate(q, v) - quaternion_to_matrix(q) * v).norm() <=
            32.0 * eps * v.norm());
      // Independent reference: Eigen's rotation of a vector by a quaternion.
      CHECK((quaternion_rotate(q, v) - q * v).norm() <= 32.0 * eps * v.norm());
    }
  }

  TEST_CASE("½ ω̂ q is the time derivative of q(t) under a constant ω (eq. 1-29)") {
    std::mt19937 rng(107);
    const double h = 1e-3;
    for (int i = 0; i < trials; ++i) {
      const Vec3 omega = random_vec(rng, 5.0);
      const Quat q0 = random_rotation(rng);
      const double t = uniform(rng, -2.0, 2.0);
      // With ω constant, q(t) = exp(ω̂ t / 2) q0: the rotation by |ω| t about ω/|ω| (Eigen),
      // composed on the left because ω is a world-frame vector.
      const auto q_of = [&](double s) {
        return (Quat(Eigen::AngleAxisd(omega.norm() * s, omega.normalized())) * q0).coeffs();
      };
      const Eigen::Vector4d fd = central_difference(q_of, t, h);
      const Quat q = Quat(q_of(t));
      // Each time derivative multiplies by ω̂/2, so |q'''| = (|ω|/2)³. Central-difference error
      // ≤ h²/6 (|ω|/2)³ per coefficient, ≤ 2 × that for the 4-vector, plus round-off ~ε/h.
      const double half_rate = 0.5 * omega.norm();
      const double tolerance = 2.0 * h * h / 6.0 * std::pow(half_rate, 3) + 16.0 * eps / h;
      CHECK((quaternion_derivative(omega, q).coeffs() - fd).norm() <= tolerance);
    }
  }

}  // TEST_SUITE
