// What the chapter-1 and chapter-2 tests draw their inputs from: seeded random vectors, rotations
// and point sets, and one rigid motion with a closed form for the checks by finite differences.
// Everything here is built with Eigen, independently of the functions under test.
#pragma once

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "kinematics/inertia.h"
#include "kinematics/math_types.h"

namespace lamina::testing {

// Unit round-off of double, the scale of every "exact up to round-off" tolerance.
constexpr double eps = std::numeric_limits<double>::epsilon();
// Random inputs per identity.
constexpr int trials = 1000;

double uniform(std::mt19937& rng, double lo, double hi);

Vec3 random_vec(std::mt19937& rng, double scale);

Vec3 random_unit(std::mt19937& rng);

// A random unit quaternion, built with Eigen so it does not depend on the code under test.
Quat random_rotation(std::mt19937& rng);

// Largest |entry| of a matrix.
double max_abs(const Mat3& m);

// A random cloud of point masses around a random centre.
std::vector<PointMass> random_points(std::mt19937& rng, int count);

// A rigid motion with a closed form, used wherever a derivative is checked by finite
// differences. The body spins at rate s about the world axis d2 while that spin precesses at
// rate Ω about the world axis d1:
//   q(t) = A(t) B(t) q0,  A = rotation by Ω t about d1,  B = rotation by s t about d2.
// Differentiating, q̇ = ½ (Ω d̂1 + s A d̂2 A*) q, so by eq. 1-29
//   ω(t) = Ω d1 + s R_A(t) d2,   ω̇(t) = Ω d1 × ω(t).
// The centre of mass moves with constant acceleration a: x(t) = x0 + v0 t + ½ a t².
struct RigidMotion {
  Vec3 d1, d2;        // precession and spin axes (unit, world frame)
  double precession;  // Ω, in rad/s
  double spin;        // s, in rad/s
  Quat q0;            // orientation at t = 0
  Vec3 x0, v0, a;     // centre of mass, its velocity at t = 0, its constant acceleration

  static RigidMotion random(std::mt19937& rng);
  Mat3 precession_matrix(double t) const;
  Quat q(double t) const;
  Mat3 rotation(double t) const { return q(t).toRotationMatrix(); }
  Vec3 omega(double t) const { return precession * d1 + spin * (precession_matrix(t) * d2); }
  Vec3 omega_dot(double t) const { return precession * d1.cross(omega(t)); }
  Vec3 x(double t) const { return x0 + v0 * t + 0.5 * a * t * t; }
  Vec3 v(double t) const { return v0 + a * t; }
  // |Ω| + |s|: every k-th time derivative of R(t) r0 is bounded by rate()ᵏ |r0|.
  double rate() const { return std::abs(precession) + std::abs(spin); }
};

// Central difference (f(t+h) − f(t−h)) / 2h. Its truncation error per component is
// h²/6 · sup|f'''|, and its round-off error about ε |f| / h.
template <class F>
auto central_difference(const F& f, double t, double h) {
  return ((f(t + h) - f(t - h)) / (2.0 * h)).eval();
}

}  // namespace lamina::testing
