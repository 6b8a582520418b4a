// Chapter 1, forces at points: the force and torque about the centre of mass (eq. 1-31..1-33)
// against the moment about the origin moved to x, over seeded random forces.
#include <doctest/doctest.h>

#include <random>

#include "kinematics/math_types.h"
#include "kinematics/wrench.h"
#include "support/kinematics_support.h"

using namespace lamina;
using namespace lamina::testing;

TEST_SUITE("Wrench") {
  TEST_CASE("forces at points add up to F = Σ F_i and τ = Σ (x_i − x) × F_i (eq. 1-31..1-33)") {
    std::mt19937 rng(117);
    for (int i = 0; i < trials; ++i) {
      const Vec3 x = random_vec(rng, 5.0);
      Wrench wrench;
      Vec3 force = Vec3::Zero(), moment_about_origin = Vec3::Zero();
      double scale = 0.0;
      for (int j = 0; j < 6; ++j) {
        const Vec3 f = random_vec(rng, 10.0);
        const Vec3 p = random_vec(rng, 5.0);
        wrench.add_at_point(f, p, x);
        force += f;
        moment_about_origin += p.cross(f);
        scale += (p.norm() + x.norm()) * f.norm();
      }
      // eq. 1-31: the same six additions in the same order, so equal to round-off of the sum.
      CHECK((wrench.force - force).norm() <= 16.0 * eps * scale);
      // Independent form of eq. 1-33: the moment about the origin moved to x,
      // Σ (x_i − x) × F_i = Σ x_i × F_i − x × Σ F_i.
      CHECK((wrench.torque - (moment_about_origin - x.cross(force))).norm() <= 8.0 * eps * scale);
    }
  }

}  // TEST_SUITE
