// Chapter 1 (kinematics): every identity of the text checked numerically over seeded random
// inputs. Each comparison states its tolerance and where the expected value comes from: an
// identity of the text, a closed form, Eigen's own implementation, or a finite difference whose
// error bound is derived next to it.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "kinematics/inertia.h"
#include "kinematics/math_types.h"
#include "kinematics/momentum.h"
#include "kinematics/particle.h"
#include "kinematics/quaternion.h"
#include "kinematics/rotation.h"
#include "kinematics/wrench.h"

namespace {

using namespace lamina;

// Unit round-off of double, the scale of every "exact up to round-off" tolerance below.
constexpr double eps = std::numeric_limits<double>::epsilon();
// Random inputs per identity.
constexpr int trials = 1000;

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Vec3 random_vec(std::mt19937& rng, double scale) {
  return Vec3(uniform(rng, -scale, scale), uniform(rng, -scale, scale),
              uniform(rng, -scale, scale));
}

Vec3 random_unit(std::mt19937& rng) {
  Vec3 d;
  do d = random_vec(rng, 1.0);
  while (d.norm() < 0.1);
  return d.normalized();
}

// A random unit quaternion, built with Eigen so it does not depend on the code under test.
Quat random_rotation(std::mt19937& rng) {
  return Quat(Eigen::AngleAxisd(uniform(rng, -M_PI, M_PI), random_unit(rng)));
}

// Largest |entry| of a matrix.
double max_abs(const Mat3& m) { return m.cwiseAbs().maxCoeff(); }

// A random cloud of point masses around a random centre.
std::vector<PointMass> random_points(std::mt19937& rng, int count) {
  const Vec3 centre = random_vec(rng, 5.0);
  std::vector<PointMass> points;
  for (int i = 0; i < count; ++i)
    points.push_back({uniform(rng, 0.1, 2.0), centre + random_vec(rng, 2.0)});
  return points;
}

double total_mass(const std::vector<PointMass>& points) {
  double m = 0.0;
  for (const PointMass& p : points) m += p.mass;
  return m;
}

// A rigid motion with a closed form, used wherever a derivative is checked by finite
// differences. The body spins at rate s about the world axis d2 while that spin precesses at
// rate Ω about the world axis d1:
//   q(t) = A(t) B(t) q0,  A = rotation by Ω t about d1,  B = rotation by s t about d2.
// Differentiating, q̇ = ½ (Ω d̂1 + s A d̂2 A*) q, so by eq. 1-29
//   ω(t) = Ω d1 + s R_A(t) d2,   ω̇(t) = Ω d1 × ω(t).
// The centre of mass moves with constant acceleration a: x(t) = x0 + v0 t + ½ a t².
// Everything here is built with Eigen, independently of the functions under test.
struct RigidMotion {
  Vec3 d1, d2;        // precession and spin axes (unit, world frame)
  double precession;  // Ω, in rad/s
  double spin;        // s, in rad/s
  Quat q0;            // orientation at t = 0
  Vec3 x0, v0, a;     // centre of mass, its velocity at t = 0, its constant acceleration

  static RigidMotion random(std::mt19937& rng) {
    return {random_unit(rng),        random_unit(rng),     uniform(rng, -2.0, 2.0),
            uniform(rng, -2.0, 2.0), random_rotation(rng), random_vec(rng, 3.0),
            random_vec(rng, 3.0),    random_vec(rng, 3.0)};
  }
  Mat3 precession_matrix(double t) const {
    return Eigen::AngleAxisd(precession * t, d1).toRotationMatrix();
  }
  Quat q(double t) const {
    return Quat(Eigen::AngleAxisd(precession * t, d1)) * Quat(Eigen::AngleAxisd(spin * t, d2)) * q0;
  }
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

}  // namespace

TEST_SUITE("Kinematics") {
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
