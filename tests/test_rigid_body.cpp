// Chapter 2, the rigid body: its planar angle, forces applied at a point (eq. 1-33) and what one
// step makes of them (eq. 2-3, 2-4), Box2D's mass and inertia for boxes and discs, bad input
// rejected where a body is created, and static bodies (eq. 5-1).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "kinematics/inertia.h"
#include "kinematics/wrench.h"
#include "motion/integrator.h"
#include "motion/rigid_body.h"
#include "support/kinematics_support.h"
#include "support/motion_support.h"

using namespace lamina;
using namespace lamina::testing;

TEST_SUITE("RigidBody") {
  TEST_CASE("planar_angle inverts planar_orientation and wraps into (−π, π]") {
    std::mt19937 rng(203);
    for (int i = 0; i < 1000; ++i) {
      const double theta = uniform(rng, -M_PI, M_PI);
      // eq. 1-19 with d = z and back: a few ε of round-off in sin, cos and atan2.
      CHECK(std::abs(planar_angle(planar_orientation(theta)) - theta) <= 8.0 * eps);
      // q and −q are the same orientation; an angle one turn away is the same angle.
      const Quat q = planar_orientation(theta + 2.0 * M_PI * std::floor(uniform(rng, -3.0, 4.0)));
      const Quat minus_q(-q.w(), -q.x(), -q.y(), -q.z());
      CHECK(std::abs(planar_angle(q) - theta) <= 64.0 * eps);
      CHECK(std::abs(planar_angle(minus_q) - theta) <= 64.0 * eps);
    }
  }

  TEST_CASE("a force through the centre of mass gives no rotation") {
    std::mt19937 rng(204);
    const double dt = 1.0 / 60.0;
    for (int trial = 0; trial < 100; ++trial) {
      RigidBody body = box_3d(random_vec(rng, 10.0), random_rotation(rng));
      const Quat q0 = body.q;
      const Vec3 f = random_vec(rng, 50.0);
      body.apply_force_at(f, body.x);
      // eq. 1-33: (x − x) × F is exactly the zero vector.
      CHECK(body.torque == Vec3::Zero());
      integrate(body, dt);
      CHECK(body.angular_velocity == Vec3::Zero());
      // q only passes through the renormalisation, which may move its last bit.
      CHECK((body.q.coeffs() - q0.coeffs()).norm() <= 4.0 * eps);
      // eq. 2-3: v = m⁻¹ F Δt.
      CHECK((body.v - f * dt / body.mass).norm() <= 4.0 * eps * body.v.norm());
    }
  }

  TEST_CASE("an off-centre force gives the torque τ = r × F and ω = I⁻¹ τ Δt (eq. 1-33, 2-4)") {
    std::mt19937 rng(205);
    const double dt = 1.0 / 60.0;
    for (int trial = 0; trial < 100; ++trial) {
      RigidBody body = box_3d(random_vec(rng, 10.0), random_rotation(rng));
      const Vec3 r = random_vec(rng, 1.0), f = random_vec(rng, 50.0);
      body.apply_force_at(f, body.x + r);
      // (x + r) − x recovers r only to ε(|x| + |r|), hence the tolerance.
      CHECK((body.torque - r.cross(f)).norm() <= 4.0 * eps * (body.x.norm() + r.norm()) * f.norm());
      // The same accumulation as chapter 1's Wrench (eq. 1-31..1-33): identical arithmetic.
      Wrench wrench;
      wrench.add_at_point(f, body.x + r, body.x);
      CHECK(body.force == wrench.force);
      CHECK(body.torque == wrench.torque);
      // eq. 2-4 against an independent inverse: Eigen's inverse of R I0 Rᵀ (R from Eigen).
      const Mat3 rotation = body.q.toRotationMatrix();
      const Mat3 inertia = rotation * body.inertia_body * rotation.transpose();
      const Vec3 expected = inertia.inverse() * r.cross(f) * dt;
      integrate(body, dt);
      CHECK((body.angular_velocity - expected).norm() <= 1e-12 * expected.norm());
    }
    // Planar: a box of Box2D's inertia m (w² + h²)/12 pushed sideways at its corner.
    RigidBody box = box_body(1.0, 0.5, 0.25, Vec3::Zero());
    box.apply_force_at(Vec3(0.0, 10.0, 0.0), Vec3(0.5, 0.25, 0.0));  // τ_z = 0.5 × 10 = 5 N·m
    integrate(box, dt);
    const double box2d_inertia = box.mass * (1.0 * 1.0 + 0.5 * 0.5) / 12.0;
    CHECK(std::abs(box.angular_velocity.z() - 5.0 / box2d_inertia * dt) <=
          4.0 * eps * box.angular_velocity.z());
  }

  TEST_CASE("box and disc bodies have Box2D's mass (density × area) and rotational inertia") {
    // Box2D 2.4 (b2PolygonShape/b2CircleShape::ComputeMass): a w × h box has m = ρ w h and
    // I = m (w² + h²)/12 about its centre; a disc m = ρ π r², I = m r²/2. Lamina's solids are
    // planar_depth = 1 m deep, so the same numbers hold with "area" read as volume.
    const double density = 3.0;
    const RigidBody box = box_body(density, 0.75, 0.25, Vec3::Zero());
    const double box_mass = density * 1.5 * 0.5;
    CHECK(std::abs(box.mass - box_mass) <= 4.0 * eps * box_mass);
    CHECK(std::abs(box.inertia_world()(2, 2) - box_mass * (1.5 * 1.5 + 0.5 * 0.5) / 12.0) <=
          8.0 * eps * box_mass);
    const RigidBody disc = disc_body(density, 0.4, Vec3::Zero());
    const double disc_mass = density * M_PI * 0.4 * 0.4;
    CHECK(std::abs(disc.mass - disc_mass) <= 4.0 * eps * disc_mass);
    CHECK(std::abs(disc.inertia_world()(2, 2) - 0.5 * disc_mass * 0.4 * 0.4) <=
          8.0 * eps * disc_mass);
    // The inverses agree with the inertia (eq. 5-1 needs them for every dynamic body).
    CHECK(std::abs(box.inverse_mass * box.mass - 1.0) <= 4.0 * eps);
    CHECK((box.inverse_inertia_world * box.inertia_world() - identity3()).cwiseAbs().maxCoeff() <=
          16.0 * eps);
  }

  TEST_CASE("bad input is rejected where a body is created, with a message") {
    const Mat3 inertia = box_inertia(1.0, 0.5, 0.5);
    const Vec3 origin = Vec3::Zero();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    using doctest::Contains;
    for (double mass : {-1.0, 0.0, nan, inf}) {
      CAPTURE(mass);
      CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(mass, inertia, origin),
                           Contains("mass must be finite and positive"), std::invalid_argument);
    }
    // The message carries the offending value.
    CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(-2.5, inertia, origin), Contains("got -2.5"),
                         std::invalid_argument);
    Mat3 skewed = inertia;
    skewed(0, 1) = 0.1;
    for (const Mat3& bad : {Mat3(Vec3(1.0, 1.0, -1.0).asDiagonal()), skewed, Mat3(nan * inertia)})
      CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(1.0, bad, origin), Contains("inertia tensor"),
                           std::invalid_argument);
    CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(1.0, inertia, Vec3(0.0, nan, 0.0)),
                         Contains("position is not finite"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(RigidBody::static_body(Vec3(inf, 0.0, 0.0)),
                         Contains("position is not finite"), std::invalid_argument);
    for (const Quat& q : {Quat(1.0, 1.0, 0.0, 0.0), Quat(0.0, 0.0, 0.0, 0.0),
                          Quat(nan, 0.0, 0.0, 0.0), Quat(1.0 + 1e-6, 0.0, 0.0, 0.0)}) {
      CHECK_THROWS_WITH_AS(RigidBody::dynamic_body(1.0, inertia, origin, q),
                           Contains("not a unit quaternion"), std::invalid_argument);
      CHECK_THROWS_WITH_AS(RigidBody::static_body(origin, q), Contains("not a unit quaternion"),
                           std::invalid_argument);
    }
    for (double bad : {0.0, -1.0, nan, inf}) {
      CAPTURE(bad);
      CHECK_THROWS_WITH_AS(box_body(1.0, bad, 0.5, origin), Contains("box half extent x"),
                           std::invalid_argument);
      CHECK_THROWS_WITH_AS(box_body(1.0, 0.5, bad, origin), Contains("box half extent y"),
                           std::invalid_argument);
      CHECK_THROWS_WITH_AS(disc_body(1.0, bad, origin), Contains("radius"), std::invalid_argument);
      CHECK_THROWS_WITH_AS(box_body(bad, 0.5, 0.5, origin), Contains("density"),
                           std::invalid_argument);
      CHECK_THROWS_WITH_AS(disc_body(bad, 0.5, origin), Contains("density"), std::invalid_argument);
    }
    CHECK_THROWS_WITH_AS(box_body(1.0, 0.5, 0.5, Vec3(nan, 0.0, 0.0)),
                         Contains("position is not finite"), std::invalid_argument);
    // Good input passes, including a unit quaternion normalised by the caller.
    CHECK_NOTHROW(
        RigidBody::dynamic_body(1.0, inertia, origin, Quat(1.0, 2.0, 3.0, 4.0).normalized()));
  }

  TEST_CASE("a static body has zero inverse mass and inertia and never moves (eq. 5-1)") {
    std::mt19937 rng(207);
    const Vec3 x(1.0, -2.0, 0.0);
    const Quat q = planar_orientation(0.7);
    for (Integration scheme : {Integration::semi_implicit, Integration::explicit_euler}) {
      std::vector<RigidBody> bodies{RigidBody::static_body(x, q), box_body(1.0, 0.5, 0.5, x)};
      CHECK(bodies[0].is_static());
      CHECK_FALSE(bodies[1].is_static());
      CHECK(bodies[0].inverse_mass == 0.0);
      CHECK(bodies[0].inverse_inertia_body == Mat3::Zero());
      CHECK(bodies[0].inverse_inertia_world == Mat3::Zero());
      for (int i = 0; i < 100; ++i) {
        for (RigidBody& b : bodies)
          b.apply_force_at(random_vec(rng, 100.0), b.x + random_vec(rng, 1.0));
        step_unconstrained(bodies, gravity, 1.0 / 60.0, scheme);
      }
      // Exact: every change is a product with m⁻¹ = 0 or I⁻¹ = 0. q + 0 only passes through the
      // renormalisation, which may move its last bit.
      CHECK(bodies[0].x == x);
      CHECK(bodies[0].v == Vec3::Zero());
      CHECK(bodies[0].angular_velocity == Vec3::Zero());
      CHECK((bodies[0].q.coeffs() - q.coeffs()).norm() <= 4.0 * eps);
      // The dynamic body beside it, stepped by the same calls, did move.
      CHECK(bodies[1].x != x);
    }
  }

}  // TEST_SUITE
