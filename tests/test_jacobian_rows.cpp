// The one point-row builder of jacobian_rows.h, seen from its two users: a contact row
// (contact_rows.cpp: ends_at_point, then write_point_row along n at the contact point c) and a
// joint's row (a DistanceConstraint between two anchors). A static body holds no block in
// either, as the world holds none (eq. 5-8). Planar scenes (x–y, y up).
//
//   contact   J = [ −nᵀ  −(r_a × n)ᵀ   nᵀ  (r_b × n)ᵀ ],  r = c − x             (eq. 4-3, 5-8)
//   distance  J = [ −uᵀ  −(r_a × u)ᵀ   uᵀ  (r_b × u)ᵀ ],  r = R r0, u = d / |d|  (jacobian_rows.h)
// With the anchors on the line through c along n (c − 0.3 n on a, c + 0.2 n on b), u = n and
// each lever differs from the contact's by a multiple of n, which adds nothing to r × n
// (n × n = 0): the two rows are the same row (in floating point, to rounding: see below).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "constraints/angle_limit.h"
#include "constraints/distance_constraint.h"
#include "constraints/jacobian_rows.h"

using namespace lamina;

namespace {

constexpr double dt = 1.0 / 60.0;  // Δt, in s (ζ only; J does not depend on it)
constexpr double beta = 0.2;       // β (ζ only)

// The contact row of bodies a and b at point c along n, as contact_rows.cpp writes it.
ConstraintRow contact_row(const std::vector<RigidBody>& bodies, int a, int b, const Vec3& c,
                          const Vec3& n) {
  ConstraintRow row;
  write_point_row(ends_at_point(bodies, a, b, c), n, row);
  return row;
}

// The row of a rod from c − 0.3 n on body a to c + 0.2 n on body b (L = 0.5 m: C = 0).
ConstraintRow rod_row_through(const std::vector<RigidBody>& bodies, int a, int b, const Vec3& c,
                              const Vec3& n) {
  const DistanceConstraint rod(anchor_at(bodies, a, c - 0.3 * n), anchor_at(bodies, b, c + 0.2 * n), 0.5);
  std::vector<ConstraintRow> rows;
  rod.write_rows(bodies, dt, beta, rows);
  REQUIRE(rows.size() == 1);
  return rows[0];
}

// The largest |entry| of the difference of two rows' Jsp.
double jsp_difference(const ConstraintRow& x, const ConstraintRow& y) {
  return std::max((x.Jsp[0] - y.Jsp[0]).cwiseAbs().maxCoeff(), (x.Jsp[1] - y.Jsp[1]).cwiseAbs().maxCoeff());
}

// Two boxes turned in the plane, and a static box (x–y, y up).
std::vector<RigidBody> three_bodies() {
  return {box_body(2.0, 0.5, 0.3, Vec3(0.3, 0.8, 0.0), 0.4),
          box_body(1.0, 0.4, 0.4, Vec3(1.1, 1.7, 0.0), -0.7),
          RigidBody::static_body(Vec3(-0.4, 0.2, 0.0), planar_orientation(0.9))};
}

const Vec3 point(0.7, 1.25, 0.0);                    // c, the contact point, in m
const Vec3 normal = Vec3(0.6, 0.8, 0.0).normalized();  // n, the contact normal, a → b

// Not exact in floating point: the rod's anchors go into the bodies' frames and back
// (r0 = Rᵀ (p − x), then R r0, eq. 1-25), its u is d/|d| rather than n, and its levers are
// c − x ∓ k n rather than c − x, each a few ulps off. Entries are ≤ 2, so 1e-14 (measured
// ≤ 2.3e-16) is rounding; a wrong block would differ by ~0.1 or more.
constexpr double rounding = 1e-14;

}  // namespace

TEST_SUITE("JacobianRows") {
  TEST_CASE("a contact row and a distance-joint row through the same point along the same axis are equal") {
    const std::vector<RigidBody> bodies = three_bodies();
    SUBCASE("two dynamic bodies: two blocks each, the same") {
      const ConstraintRow contact = contact_row(bodies, 0, 1, point, normal);
      const ConstraintRow rod = rod_row_through(bodies, 0, 1, point, normal);
      CHECK(contact.Jmap == std::array<int, 2>{0, 1});
      CHECK(rod.Jmap == contact.Jmap);
      CHECK(jsp_difference(rod, contact) <= rounding);
      // eq. 4-3 written out for body b: [nᵀ ((c − x_b) × n)ᵀ]
      CHECK((contact.Jsp[1].head<3>() - normal).norm() == 0.0);
      CHECK((contact.Jsp[1].tail<3>() - (point - bodies[1].x).cross(normal)).norm() == 0.0);
    }
    SUBCASE("a static body a: one block, body b's, in both (Jmap = {b, −1})") {
      const ConstraintRow contact = contact_row(bodies, 2, 1, point, normal);
      const ConstraintRow rod = rod_row_through(bodies, 2, 1, point, normal);
      CHECK(contact.Jmap == std::array<int, 2>{1, world});
      CHECK(rod.Jmap == contact.Jmap);
      CHECK(jsp_difference(rod, contact) <= rounding);
      // eq. 5-8: the static body's columns are left out, the moving body's block is as above
      CHECK(contact.Jsp[1] == Vec6::Zero());
      CHECK((contact.Jsp[0].head<3>() - normal).norm() == 0.0);
      CHECK((contact.Jsp[0].tail<3>() - (point - bodies[1].x).cross(normal)).norm() == 0.0);
    }
  }

  TEST_CASE("an angle limit against a static body is the row against the world") {
    // J = s [ 0ᵀ −ẑᵀ 0ᵀ ẑᵀ ] without levers: exact, the same numbers copied (no rounding)
    const std::vector<RigidBody> bodies = three_bodies();
    for (const LimitSide side : {LimitSide::lower, LimitSide::upper}) {
      std::vector<ConstraintRow> rows;
      AngleLimit(2, 1, 0.1, side).write_rows(bodies, dt, beta, rows);
      AngleLimit(world, 1, 0.1, side).write_rows(bodies, dt, beta, rows);
      const double s = side == LimitSide::lower ? 1.0 : -1.0;
      Vec6 expected = Vec6::Zero();
      expected[5] = s;  // body b's block, +s ẑ on ω
      for (const ConstraintRow& row : rows) {
        CHECK(row.Jmap == std::array<int, 2>{1, world});
        CHECK(row.Jsp[0] == expected);
        CHECK(row.Jsp[1] == Vec6::Zero());
      }
    }
  }
}
