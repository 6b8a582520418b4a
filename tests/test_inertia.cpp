// Chapter 1, "Inertia tensor": the centre of mass (eq. 1-1), point-set inertia (eq. 1-34..1-36)
// converging to the closed forms of the box and the cylinder, and I = R I0 Rᵀ for a moved body
// (eq. 1-37). Each comparison states its tolerance and where the expected value comes from: an
// identity of the text, a closed form, or the error of the midpoint rule derived next to it.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kinematics/inertia.h"
#include "kinematics/math_types.h"
#include "kinematics/particle.h"
#include "support/kinematics_support.h"

using namespace lamina;
using namespace lamina::testing;

TEST_SUITE("Inertia") {
  TEST_CASE("the centre of mass is the mass-weighted mean of the points (eq. 1-1)") {
    std::mt19937 rng(109);
    // Analytic: 1 kg at x = 0 and 3 kg at x = 4 balance at x = 3 (exact in binary).
    CHECK(centre_of_mass({{1.0, Vec3(0, 0, 0)}, {3.0, Vec3(4, 0, 0)}}) == Vec3(3, 0, 0));
    for (int i = 0; i < trials; ++i) {
      const std::vector<PointMass> points = random_points(rng, 20);
      const Vec3 c = centre_of_mass(points);
      // Defining property: Σ m_i (x_i − x) = 0, to the round-off of the sums (relative to
      // Σ m_i |x_i|).
      Vec3 moment = Vec3::Zero();
      double scale = 0.0;
      for (const PointMass& p : points) {
        moment += p.mass * (p.position - c);
        scale += p.mass * p.position.norm();
      }
      CHECK(moment.norm() <= 64.0 * eps * scale);
    }
  }

  TEST_CASE("a grid of point masses in a box converges to box_inertia as 1/N² (eq. 1-34..1-36)") {
    // N³ points at the cell centres of a cuboid (half extents hx, hy, depth planar_depth), each of
    // mass m/N³. For the midpoint rule, Σ over cells of (cell centre)² = ∫ x² − N cell³/12, so the
    // grid's inertia is exactly (1 − 1/N²) × the closed form: the relative error is 1/N².
    const double m = 3.0, hx = 0.7, hy = 0.3, hz = 0.5 * planar_depth;
    const Vec3 centre(1.5, -2.0, 0.25);
    const Mat3 closed = box_inertia(m, hx, hy);
    double previous = 0.0;
    for (int n : {4, 8, 16, 32}) {
      std::vector<PointMass> points;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          for (int k = 0; k < n; ++k)
            points.push_back({m / (n * n * n), centre + Vec3(hx * (2.0 * (i + 0.5) / n - 1.0),
                                                             hy * (2.0 * (j + 0.5) / n - 1.0),
                                                             hz * (2.0 * (k + 0.5) / n - 1.0))});
      // eq. 1-1 on a symmetric grid: the centre of the box, to round-off of |centre|.
      const Vec3 c = centre_of_mass(points);
      CHECK((c - centre).norm() <= 1e3 * eps * centre.norm());
      const Mat3 grid = point_set_inertia(points, c);
      const double error = (grid - closed).norm() / closed.norm();
      MESSAGE("box grid N = " << n << ": relative inertia error " << error);
      // The midpoint-rule analysis above: error · N² = 1 (round-off of N³ terms ≪ 1e-9).
      CHECK(std::abs(error * n * n - 1.0) <= 1e-9);
      if (previous > 0.0) CHECK(std::abs(previous / error - 4.0) <= 1e-6);  // halve the cell: ÷4
      previous = error;
    }
  }

  TEST_CASE("a polar grid of point masses in a cylinder converges to disc_inertia as 1/N²") {
    // Cell centres of a polar grid: N rings of width δr = R/N, 8 angular sectors, N slices along z.
    // Each point carries the mass of its cell, m × r_j δr δθ δz / (π R² L), which is exact.
    // Midpoint rule in r: Σ r_j³ δr = R⁴/4 − δr² R²/8, so I_zz(grid) = m R²/2 (1 − 1/(2N²));
    // in z, as for the box, (1 − 1/N²); the 8 angles integrate cos², sin², sin cos exactly.
    // Every error term is ∝ 1/N², so the error falls by exactly 4 when N doubles.
    const double m = 2.0, radius = 0.8, depth = planar_depth;
    const int sectors = 8;
    const Mat3 closed = disc_inertia(m, radius);
    double previous = 0.0;
    for (int n : {4, 8, 16, 32}) {
      const double dr = radius / n, dtheta = 2.0 * M_PI / sectors, dz = depth / n;
      std::vector<PointMass> points;
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < sectors; ++k)
          for (int l = 0; l < n; ++l) {
            const double r = (j + 0.5) * dr, theta = (k + 0.5) * dtheta;
            const double cell = r * dr * dtheta * dz;
            points.push_back(
                {m * cell / (M_PI * radius * radius * depth),
                 Vec3(r * std::cos(theta), r * std::sin(theta), (l + 0.5) * dz - 0.5 * depth)});
          }
      const Mat3 grid = point_set_inertia(points, centre_of_mass(points));
      // The analysis above, term by term (the expected grid inertia in closed form).
      const double zz = 0.5 * m * radius * radius * (1.0 - 0.5 / (n * n));
      const double across = 0.5 * zz + m * depth * depth / 12.0 * (1.0 - 1.0 / (n * n));
      const Mat3 expected = Vec3(across, across, zz).asDiagonal();
      CHECK(max_abs(grid - expected) <= 1e-12 * closed.norm());
      const double error = (grid - closed).norm() / closed.norm();
      MESSAGE("cylinder grid N = " << n << ": relative inertia error " << error);
      if (previous > 0.0) CHECK(std::abs(previous / error - 4.0) <= 1e-6);
      previous = error;
    }
  }

  TEST_CASE("a rotated point set has inertia R I0 Rᵀ (eq. 1-37)") {
    std::mt19937 rng(110);
    for (int i = 0; i < trials; ++i) {
      const std::vector<PointMass> body = random_points(rng, 12);
      const Vec3 c = centre_of_mass(body);
      const Mat3 inertia_body = point_set_inertia(body, c);
      // Move the set rigidly: new centre x, rotation R (Eigen), eq. 1-25 for each point.
      const Mat3 r = random_rotation(rng).toRotationMatrix();
      const Vec3 x = random_vec(rng, 10.0);
      std::vector<PointMass> moved;
      for (const PointMass& p : body)
        moved.push_back({p.mass, particle_position(x, r, p.position - c)});
      const Mat3 direct = point_set_inertia(moved, centre_of_mass(moved));
      // Both are sums of 12 terms of size m |r|², each rotated: round-off ≤ 64 ε |I|.
      CHECK(max_abs(world_inertia(r, inertia_body) - direct) <= 64.0 * eps * max_abs(direct));
    }
  }

}  // TEST_SUITE
