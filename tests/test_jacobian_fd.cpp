// J V against dC/dt (chapter 3, eq. 3-6..3-8): every kind of row Lamina writes — a contact row
// as contact_rows.cpp writes it (eq. 4-3), an incline (eq. 3-1), a distance constraint, the two
// rows of a revolute joint and an angle limit — at random planar states, against the central
// difference of C computed from the constraint's own definition, not from the row.
//
//   state at time τ   x(τ) = x + v τ,  q(τ) = q_z(ω τ) q   (the motion the velocities V describe)
//   D_h = (C(state at +h) − C(state at −h)) / (2h)
//   Taylor: D_h = Ċ + h² C'''(ξ)/6, so |D_h − Ċ| ≤ h² max|C'''| / 6 + round-off.
// Round-off: C is evaluated to a few ulps of the coordinates (|x| ≤ 3 m, ~1e-15 m) at both ends,
// so the quotient carries ≤ 1e-14 m / h. With h = 1e-5 s:
//   tolerance = max|C'''| h²/6 + 1e-14/h = max|C'''| · 1.7e-11 + 1e-9   (in m/s or rad/s).
// max|C'''| is bounded from the sampled ranges below (|v| ≤ √2 m/s, |ω| ≤ 1 rad/s, levers
// |r| ≤ 0.71 m, so a body point has |ṗ| ≤ 2.13 m/s, |p̈| ≤ ω²|r| ≤ 0.71, |p⃛| ≤ |ω|³|r| ≤ 0.71):
//   angle limit  C linear in the angles                      C''' = 0
//   incline, revolute  C linear in one or two points         |C'''| ≤ 2 · 0.71 ≤ 1.5
//   contact      C = d·n, d = p2 − p1 (|d| ≤ 0.1 m), n turning at ω_ref
//                |C'''| ≤ |d⃛| + 3|d̈||ω| + 3|ḋ|ω² + |d||ω|³ ≤ 1.42 + 4.3 + 12.8 + 0.1 ≤ 20
//   distance     C = |d| − L with |d| ≥ 0.5 m: |C'''| ≤ |d⃛| + 3|ḋ||d̈|/|d| + 3|ḋ|³/|d|² ≤ 1000
// A row that is wrong (a lever with the wrong sign, a missing block) misses by |ω||r| ~ 0.1–1.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "constraints/angle_limit.h"
#include "constraints/distance_constraint.h"
#include "constraints/incline_constraint.h"
#include "constraints/revolute_joint.h"
#include "contact/contact_rows.h"
#include "contact/planar.h"

using namespace lamina;

namespace {

constexpr double h = 1e-5;         // the finite-difference step, in s
constexpr double dt = 1.0 / 60.0;  // Δt, in s (ζ only: J does not depend on it)
constexpr double beta = 0.2;       // β (ζ only)
constexpr int states = 200;        // random states per row type

// The tolerance on |J V − D_h| for a constraint whose |C'''| ≤ third (see the top of the file).
double tolerance(double third) { return third * h * h / 6.0 + 1e-14 / h; }

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Vec3 random_point(std::mt19937& rng, double half) {
  return Vec3(uniform(rng, -half, half), uniform(rng, -half, half), 0.0);
}

Vec3 random_direction(std::mt19937& rng) {
  const double angle = uniform(rng, -M_PI, M_PI);
  return Vec3(std::cos(angle), std::sin(angle), 0.0);
}

// Body 0 is static (the ground: it holds no block, eq. 5-8); bodies 1..3 move, each with a
// random planar x in [−2, 2]² m, θ, v in [−1, 1]² m/s and ω in [−1, 1] rad/s.
std::vector<RigidBody> random_bodies(std::mt19937& rng) {
  std::vector<RigidBody> bodies{RigidBody::static_body(random_point(rng, 2.0), planar_orientation(0.3))};
  for (int b = 1; b < 4; ++b) {
    RigidBody body = box_body(1.0, 0.5, 0.3, random_point(rng, 2.0), uniform(rng, -M_PI, M_PI));
    body.v = random_point(rng, 1.0);
    body.angular_velocity = Vec3(0.0, 0.0, uniform(rng, -1.0, 1.0));
    bodies.push_back(body);
  }
  return bodies;
}

// The bodies moved along their velocities for a time τ: x + v τ, q turned by ω τ about z.
std::vector<RigidBody> moved(std::vector<RigidBody> bodies, double tau) {
  for (RigidBody& body : bodies) {
    body.x += body.v * tau;
    body.q = planar_orientation(body.angular_velocity.z() * tau) * body.q;
    body.update_derived();
  }
  return bodies;
}

// J V of a written row (eq. 3-8): each block against its body's [v ω].
double row_times_velocity(const ConstraintRow& row, const std::vector<RigidBody>& bodies) {
  double sum = 0.0;
  for (int k = 0; k < 2; ++k) {
    if (row.Jmap[k] < 0) continue;
    const RigidBody& body = bodies[static_cast<std::size_t>(row.Jmap[k])];
    sum += row.Jsp[k].head<3>().dot(body.v) + row.Jsp[k].tail<3>().dot(body.angular_velocity);
  }
  return sum;
}

// A body point from its body-frame offset: p = x + R r (eq. 1-25); the world's is r itself.
Vec3 point_of(const std::vector<RigidBody>& bodies, int body, const Vec3& r) {
  if (body == world) return r;
  const RigidBody& b = bodies[static_cast<std::size_t>(body)];
  return b.x + b.rotation * r;
}

// A body's angle about z from its R (θ = atan2(R10, R00)); the world's is 0.
double angle_of(const std::vector<RigidBody>& bodies, int body) {
  if (body == world) return 0.0;
  const Mat3& R = bodies[static_cast<std::size_t>(body)].rotation;
  return std::atan2(R(1, 0), R(0, 0));
}

// The central difference D_h of C along the bodies' motion.
template <class PositionError>
double central_difference(const std::vector<RigidBody>& bodies, PositionError C) {
  return (C(moved(bodies, h)) - C(moved(bodies, -h))) / (2.0 * h);
}

// Two different body indices among the world (−1) and bodies 1..3 (the static body 0 is used
// by the contacts).
std::array<int, 2> random_pair(std::mt19937& rng) {
  std::uniform_int_distribution<int> pick(0, 3);
  int a = pick(rng), b = pick(rng);
  while (b == a || b == 0) b = pick(rng);
  if (a == 0) a = world;
  return {a, b};
}

// An anchor within 0.5 m of the body's centre (|r| ≤ 0.71 m), or near the origin for the world.
Anchor random_anchor(std::mt19937& rng, const std::vector<RigidBody>& bodies, int body) {
  return anchor_at(bodies, body, point_of(bodies, body, Vec3::Zero()) + random_point(rng, 0.5));
}

// The rows of one type: each J V against D_h, to the tolerance of that type's max|C'''|; keeps
// the largest miss for the message.
class RowCheck {
 public:
  explicit RowCheck(double third) : tolerance_(tolerance(third)) {}

  // `dropped` is added to J V: a term the row leaves out on purpose (the contact row's).
  template <class PositionError>
  void check(const ConstraintRow& row, const std::vector<RigidBody>& bodies, PositionError C,
             double dropped = 0.0) {
    const double miss = std::abs(row_times_velocity(row, bodies) + dropped - central_difference(bodies, C));
    worst_ = std::max(worst_, miss);
    CHECK(miss <= tolerance_);
  }
  // Row `row` of a constraint, written for the bodies now.
  template <class PositionError>
  void check(const Constraint& constraint, const std::vector<RigidBody>& bodies, PositionError C,
             std::size_t row = 0) {
    std::vector<ConstraintRow> rows;
    constraint.write_rows(bodies, dt, beta, rows);
    REQUIRE(row < rows.size());
    check(rows[row], bodies, C);
  }
  // "largest |J V − D_h| = …, tolerance …"
  std::string summary() const {
    std::ostringstream out;
    out << "largest |J V − D_h| = " << worst_ << ", tolerance " << tolerance_;
    return out.str();
  }

 private:
  double tolerance_;    // in m/s or rad/s
  double worst_ = 0.0;  // the largest miss so far
};

}  // namespace

TEST_SUITE("JacobianFiniteDifference") {
  TEST_CASE("incline row: J V = d/dt (x − p)·N (eq. 3-1, 3-2), both kinds") {
    std::mt19937 rng(101);
    RowCheck rows_of(1.5);
    for (int trial = 0; trial < states; ++trial) {
      const std::vector<RigidBody> bodies = random_bodies(rng);
      const int body = 1 + trial % 3;
      const Vec3 p = random_point(rng, 2.0), N = random_direction(rng);
      const InclineKind kind = trial % 2 == 0 ? InclineKind::bilateral : InclineKind::one_sided;
      // eq. 3-1: C = (x − p)·N
      const auto C = [&](const std::vector<RigidBody>& b) { return (b[body].x - p).dot(N); };
      rows_of.check(InclineConstraint(body, p, N, kind), bodies, C);
    }
    MESSAGE("incline: " << rows_of.summary() << " m/s");
  }

  TEST_CASE("distance row: J V = d/dt (|p_b − p_a| − L)") {
    std::mt19937 rng(102);
    RowCheck rows_of(1000.0);
    for (int trial = 0; trial < states; ++trial) {
      const std::vector<RigidBody> bodies = random_bodies(rng);
      const std::array<int, 2> pair = random_pair(rng);  // named, not bound: lambdas below use them
      const int a = pair[0], b = pair[1];
      // ends at least 0.5 m apart
      Anchor end_a, end_b;
      do {
        end_a = random_anchor(rng, bodies, a);
        end_b = random_anchor(rng, bodies, b);
      } while ((point_of(bodies, b, end_b.local) - point_of(bodies, a, end_a.local)).norm() < 0.5);
      const double L = uniform(rng, 0.5, 2.0);
      const auto C = [&](const std::vector<RigidBody>& s) {
        return (point_of(s, b, end_b.local) - point_of(s, a, end_a.local)).norm() - L;
      };
      rows_of.check(DistanceConstraint(end_a, end_b, L), bodies, C);
    }
    MESSAGE("distance: " << rows_of.summary() << " m/s");
  }

  TEST_CASE("revolute rows: J V = d/dt of x̂·(p_b − p_a) and ŷ·(p_b − p_a)") {
    std::mt19937 rng(103);
    RowCheck rows_of(1.5);
    for (int trial = 0; trial < states; ++trial) {
      const std::vector<RigidBody> bodies = random_bodies(rng);
      const std::array<int, 2> pair = random_pair(rng);  // named, not bound: lambdas below use them
      const int a = pair[0], b = pair[1];
      // the pins need not meet: J holds for any C, and a joint with an error is when it matters
      const Anchor pin_a = random_anchor(rng, bodies, a), pin_b = random_anchor(rng, bodies, b);
      const RevoluteJoint pin(pin_a, pin_b);
      for (std::size_t k = 0; k < 2; ++k) {
        const Vec3 e = k == 0 ? Vec3::UnitX() : Vec3::UnitY();  // rows x, then y
        const auto C = [&](const std::vector<RigidBody>& s) {
          return e.dot(point_of(s, b, pin_b.local) - point_of(s, a, pin_a.local));
        };
        rows_of.check(pin, bodies, C, k);
      }
    }
    MESSAGE("revolute: " << rows_of.summary() << " m/s");
  }

  TEST_CASE("angle-limit row: J V = d/dt s(θ_b − θ_a − θ_L) (eq. 3-17 for an angle)") {
    std::mt19937 rng(104);
    RowCheck rows_of(0.0);
    for (int trial = 0; trial < states; ++trial) {
      const std::vector<RigidBody> bodies = random_bodies(rng);
      const std::array<int, 2> pair = random_pair(rng);  // named, not bound: lambdas below use them
      const int a = pair[0], b = pair[1];
      const double relative = angle_of(bodies, b) - angle_of(bodies, a);
      // θ_b − θ_a away from ±π, where the relative angle wraps (angle_limit.h: a known limit)
      if (std::abs(std::remainder(relative, 2.0 * M_PI)) > 3.0) continue;
      const LimitSide side = trial % 2 == 0 ? LimitSide::lower : LimitSide::upper;
      const double limit = uniform(rng, -3.0, 3.0), s = side == LimitSide::lower ? 1.0 : -1.0;
      const auto C = [&](const std::vector<RigidBody>& st) {
        return s * (std::remainder(angle_of(st, b) - angle_of(st, a), 2.0 * M_PI) - limit);
      };
      rows_of.check(AngleLimit(a, b, limit, side), bodies, C);
    }
    MESSAGE("angle limit: " << rows_of.summary() << " rad/s");
  }

  // The contact row (eq. 4-3) drops the text's term (x2 + r2 − x1 − r1)·(ω1 × n1) of eq. 4-2, and
  // Lamina's levers both end at the midpoint c = (p1 + p2)/2 (contact.h), not at each body's own
  // point p_k. With d = p2 − p1, n turning with the reference body and u = ẑ × n:
  //   Ċ   = n·(v2 + ω2×(p2 − x2) − v1 − ω1×(p1 − x1)) + d·(ω_ref × n)      (eq. 4-2)
  //   J V = n·(v2 + ω2×(c − x2)  − v1 − ω1×(c − x1))                        (eq. 4-3)
  //   Ċ − J V = n·(ω2 × d/2) + n·(ω1 × d/2) + d·(ω_ref × n) = (ω_ref − (ω1 + ω2)/2) (d·u)
  //           = ½ (ω_ref − ω_other) (d·u)   in the plane (n·(ω×d) = −ω d·u, d·(ω×n) = ω d·u).
  // So J V = Ċ exactly when d ∥ n — at separation 0 (d = 0), and for any separation when the two
  // points lie on one normal, as the narrow phase makes them (drift 0) — or when the bodies turn
  // alike. The text's own levers (r_k to p_k) would leave ω_ref (d·u): exact at separation 0 or
  // for a reference body that does not turn. Lamina's midpoint halves it and splits it between
  // the two bodies. Both cases are checked: drift 0, and drift ≠ 0 with the term added back.
  TEST_CASE("contact row as contact_rows.cpp writes it: J V = dC/dt when d ∥ n, else the dropped term") {
    std::mt19937 rng(105);
    RowCheck aligned(20.0), drifting(20.0);
    double uncorrected = 0.0;  // the largest |J V − D_h| with drift, the term left out, in m/s
    for (int trial = 0; trial < 2 * states; ++trial) {
      const std::vector<RigidBody> bodies = random_bodies(rng);
      // body 1 of eq. 4-1 is the lower index: the static ground (0) or a moving body
      const int first = trial % 4 == 0 ? 0 : 1 + trial % 2, second = 3;
      const bool drift = trial % 2 == 1;
      const Vec3 c = 0.5 * (bodies[first].x + bodies[second].x) + random_point(rng, 0.3);
      const Vec2 n = random_direction(rng).head<2>(), u = tangent_of(n);
      const double separation = uniform(rng, -0.05, 0.05), slide = drift ? uniform(rng, -0.05, 0.05) : 0.0;
      const Vec2 p1 = c.head<2>() - 0.5 * separation * n, p2 = p1 + separation * n + slide * u;
      const Pose2 pose1 = planar_pose(bodies[first]), pose2 = planar_pose(bodies[second]);
      ContactPair pair;
      pair.bodies = {first, second};
      pair.friction = 0.5;
      pair.count = 1;
      Contact& contact = pair.contacts[0];
      contact.reference = trial % 3 == 0 ? 1 : 0;
      contact.anchor = {pose1.to_body(p1), pose2.to_body(p2)};
      contact.local_normal = (contact.reference == 0 ? pose1 : pose2).R.transpose() * n;
      place(contact, pose1, pose2);  // the contact as the cache re-places it (eq. 5-12)
      std::vector<ConstraintRow> rows;
      std::vector<double> lambda;
      std::vector<ContactPair> pairs{pair};
      add_contact_rows(pairs, bodies, ContactSettings{}, StepSettings{}, rows, lambda);
      const ConstraintRow& row = rows[static_cast<std::size_t>(pairs[0].contacts[0].row)];
      // eq. 4-1: C = (x2 + r2 − x1 − r1)·n1 from the anchors, n turning with its body
      const Vec3 r1(contact.anchor[0].x(), contact.anchor[0].y(), 0.0), r2(contact.anchor[1].x(), contact.anchor[1].y(), 0.0);
      const Vec3 n_local(contact.local_normal.x(), contact.local_normal.y(), 0.0);
      const int reference = contact.reference == 0 ? first : second;
      const auto C = [&](const std::vector<RigidBody>& s) {
        const Vec3 n_now = s[reference].rotation * n_local;
        return (point_of(s, second, r2) - point_of(s, first, r1)).dot(n_now);
      };
      const double omega_ref = bodies[reference].angular_velocity.z();
      const double omega_other = bodies[reference == first ? second : first].angular_velocity.z();
      const double dropped = 0.5 * (omega_ref - omega_other) * slide;  // ½ (ω_ref − ω_other)(d·u)
      (drift ? drifting : aligned).check(row, bodies, C, dropped);
      if (drift) {
        uncorrected = std::max(uncorrected, std::abs(row_times_velocity(row, bodies) - central_difference(bodies, C)));
      }
    }
    // the term is real: without it the drifting states miss by far more than the tolerance
    CHECK(uncorrected > 1000.0 * tolerance(20.0));
    MESSAGE("contact, d ∥ n: " << aligned.summary() << " m/s; with drift, ½(ω_ref − ω_other)(d·u) "
            << "added to J V: " << drifting.summary() << " m/s (without it: " << uncorrected << " m/s)");
  }
}
