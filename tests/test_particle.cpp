// Chapter 1, a particle fixed in a rigid body: its velocity (eq. 1-30) and acceleration
// (eq. 1-49) are the time derivatives of its position (eq. 1-25) along a rigid motion with a
// closed form, checked by central differences with the error bounds derived next to them.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "kinematics/math_types.h"
#include "kinematics/particle.h"
#include "support/kinematics_support.h"

using namespace lamina;
using namespace lamina::testing;

TEST_SUITE("Particle") {
  TEST_CASE(
      "particle velocity and acceleration are the time derivatives along a rigid motion "
      "(eq. 1-25, 1-30, 1-49)") {
    std::mt19937 rng(114);
    const double h = 1e-4;
    for (int i = 0; i < trials; ++i) {
      const RigidMotion motion = RigidMotion::random(rng);
      const Vec3 r0 = random_vec(rng, 1.0);
      const double t = uniform(rng, -2.0, 2.0);
      const auto position = [&](double s) {  // eq. 1-25
        return particle_position(motion.x(s), motion.rotation(s), r0);
      };
      const auto velocity = [&](double s) {  // eq. 1-30
        return particle_velocity(motion.v(s), motion.omega(s), motion.x(s), position(s));
      };
      const double k = motion.rate();
      const double scale = motion.x(t).norm() + motion.v(t).norm() + motion.a.norm() + 1.0;
      // x_i''' = (R r0)''' (x is quadratic in t), |(R r0)'''| ≤ k³ |r0|: error ≤ √3 h²/6 k³ |r0|.
      CHECK((velocity(t) - central_difference(position, t, h)).norm() <=
            h * h * std::pow(k, 3) * r0.norm() + 1e3 * eps * scale / h);
      // v_i''' = (ω × R r0)''' ≤ 3 k⁴ |r0| by Leibniz with |ω⁽ʲ⁾| ≤ k^(j+1) (RigidMotion):
      // error ≤ √3 h²/6 · 3 k⁴ |r0| < h² k⁴ |r0|.
      const Vec3 r = position(t) - motion.x(t);
      const Vec3 a_i = particle_acceleration(motion.a, motion.omega_dot(t), motion.omega(t), r);
      CHECK((a_i - central_difference(velocity, t, h)).norm() <=
            h * h * std::pow(k, 4) * r0.norm() + 1e3 * eps * scale / h);
    }
  }

}  // TEST_SUITE
