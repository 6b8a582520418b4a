// Chapter 1, "Rotation": Skew(d) and the cross product, Rodrigues' formula and the rotation about
// z, checked against Eigen and the quaternion form over seeded random inputs, and Ṙ Rᵀ = Skew(ω)
// along a rigid rotation by finite differences. Each comparison states its tolerance and where
// the expected value comes from: an identity of the text, Eigen's own implementation, or a finite
// difference whose error bound is derived next to it.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "kinematics/math_types.h"
#include "kinematics/quaternion.h"
#include "kinematics/rotation.h"
#include "support/kinematics_support.h"

using namespace lamina;
using namespace lamina::testing;

TEST_SUITE("Rotation") {
  TEST_CASE("skew(d) r equals the cross product d × r (eq. 1-2, 1-3)") {
    std::mt19937 rng(101);
    for (int i = 0; i < trials; ++i) {
      const Vec3 d = random_vec(rng, 10.0);
      const Vec3 r = random_vec(rng, 10.0);
      // Identity 1-3; each component is a difference of two products, so round-off ≤ 4 ε |d||r|.
      CHECK((skew(d) * r - d.cross(r)).norm() <= 4.0 * eps * d.norm() * r.norm());
      // Skew(d) is antisymmetric (eq. 1-2).
      CHECK(skew(d) + skew(d).transpose() == Mat3::Zero());
    }
  }

  TEST_CASE("skew(d)² equals d dᵀ − E for a unit axis d (eq. 1-15)") {
    std::mt19937 rng(102);
    for (int i = 0; i < trials; ++i) {
      const Vec3 d = random_unit(rng);
      const Mat3 s = skew(d);
      // Identity 1-15; entries are O(1) sums of three products: round-off ≤ 8 ε.
      CHECK(max_abs(s * s - (d * d.transpose() - identity3())) <= 8.0 * eps);
    }
  }

  TEST_CASE(
      "Rodrigues, the quaternion matrix and Eigen's AngleAxis are the same rotation "
      "(eq. 1-4, 1-19, 1-22)") {
    std::mt19937 rng(103);
    for (int i = 0; i < trials; ++i) {
      const Vec3 d = random_unit(rng);
      const double angle = uniform(rng, -3.0 * M_PI, 3.0 * M_PI);
      const Mat3 eigen = Eigen::AngleAxisd(angle, d).toRotationMatrix();
      const Quat q = quaternion_from_axis_angle(d, angle);
      // Entries of a rotation are ≤ 1 and each formula is a few products of such numbers plus a
      // sin/cos (≤ 1 ulp each): 16 ε leaves a margin of ~4 over the worst case seen.
      CHECK(max_abs(rodrigues(d, angle) - eigen) <= 16.0 * eps);
      CHECK(max_abs(quaternion_to_matrix(q) - eigen) <= 16.0 * eps);
      // eq. 1-19 against Eigen's axis-angle quaternion, coefficient by coefficient.
      CHECK((q.coeffs() - Quat(Eigen::AngleAxisd(angle, d)).coeffs()).cwiseAbs().maxCoeff() <=
            4.0 * eps);
      // eq. 1-22 against Eigen's own quaternion → matrix, for any unit quaternion.
      const Quat p = random_rotation(rng);
      CHECK(max_abs(quaternion_to_matrix(p) - p.toRotationMatrix()) <= 16.0 * eps);
    }
  }

  TEST_CASE("rotation about z is Rodrigues with d = z (eq. 1-5)") {
    std::mt19937 rng(104);
    for (int i = 0; i < trials; ++i) {
      const double angle = uniform(rng, -3.0 * M_PI, 3.0 * M_PI);
      // eq. 1-5 is eq. 1-4 with d = z; the same sin and cos, so agreement to a few ε.
      CHECK(max_abs(rotation_z(angle) - rodrigues(Vec3::UnitZ(), angle)) <= 4.0 * eps);
    }
  }

  TEST_CASE("Ṙ Rᵀ is Skew(ω) and ṙ_i = ω × r_i along a rigid rotation (eq. 1-27, 1-28)") {
    std::mt19937 rng(108);
    const double h = 1e-4;
    for (int i = 0; i < trials; ++i) {
      const RigidMotion motion = RigidMotion::random(rng);
      const double t = uniform(rng, -2.0, 2.0);
      const auto r_of = [&](double s) { return motion.rotation(s); };
      const Mat3 r_dot = central_difference(r_of, t, h);
      // |R'''| ≤ k³ with k = rate() (see RigidMotion): error ≤ h²/6 k³ per entry.
      const double tolerance = h * h / 6.0 * std::pow(motion.rate(), 3) + 16.0 * eps / h;
      CHECK(max_abs(r_dot * motion.rotation(t).transpose() - skew(motion.omega(t))) <=
            2.0 * tolerance);
      // eq. 1-28 for a body-frame offset r0: d/dt (R r0) = ω × (R r0).
      const Vec3 r0 = random_vec(rng, 1.0);
      CHECK((r_dot * r0 - motion.omega(t).cross(motion.rotation(t) * r0)).norm() <=
            3.0 * tolerance * r0.norm());
    }
  }

}  // TEST_SUITE
