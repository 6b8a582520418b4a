// Chapters 4–5 in motion, Lamina alone: the contact cache of Fig 4-2..4-5, resting and sliding
// contacts with friction, stacks, restitution, the chapter-5 limit t → ∞, and planarity.
// Scenes lie in the x–y plane, y up; the ground is a static box whose top is y = 0.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "beyond/methods.h"
#include "constraints/jacobian_rows.h"
#include "constraints/revolute_joint.h"
#include "contact/contact_cache.h"
#include "contact/world.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, in m/s²

Material material(double friction, double restitution = 0.0) { return {friction, restitution}; }

// Ground (body 0, half extents 20 × 0.5, top at y = 0) and a unit box (body 1, m = 1 kg).
World box_on_ground(const WorldSettings& settings, double y, double angle, double friction = 0.6) {
  World world(settings);
  world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, material(friction));
  world.add_box(1.0, 0.5, 0.5, Vec3(0.0, y, 0.0), angle, material(friction));
  return world;
}

void run(World& world, int steps) {
  for (int i = 0; i < steps; ++i) world.step();
}

bool at_rest(const RigidBody& body) {
  return body.v.norm() < 1e-3 && body.angular_velocity.norm() < 1e-3;
}

// The largest |component| a planar scene keeps at exactly zero.
double out_of_plane(const RigidBody& body) {
  return std::max({std::abs(body.x.z()), std::abs(body.v.z()), std::abs(body.angular_velocity.x()),
                   std::abs(body.angular_velocity.y()), std::abs(body.q.x()), std::abs(body.q.y())});
}

// Every body of two worlds in the same state, bit for bit.
void check_identical(const World& a, const World& b) {
  REQUIRE(a.bodies().size() == b.bodies().size());
  for (size_t k = 0; k < a.bodies().size(); ++k) {
    CHECK(a.bodies()[k].x == b.bodies()[k].x);
    CHECK(a.bodies()[k].v == b.bodies()[k].v);
    CHECK(a.bodies()[k].q.coeffs() == b.bodies()[k].q.coeffs());
    CHECK(a.bodies()[k].angular_velocity == b.bodies()[k].angular_velocity);
  }
}

// Boxes and discs dropped in a heap: many pairs of every type, sliding, rolling, tumbling.
World heap(const WorldSettings& settings) {
  World world(settings);
  world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, material(0.6));
  for (int i = 0; i < 12; ++i) {
    const Vec3 x(0.37 * (i % 4) - 0.6, 0.8 + 1.1 * (i / 4), 0.0);
    if (i % 3 == 2) {
      world.add_circle(1.0, 0.3, x, material(0.4, 0.3));
    } else {
      world.add_box(1.0, 0.4, 0.3, x, 0.2 * i, material(0.6));
    }
  }
  return world;
}

}  // namespace

TEST_SUITE("ContactCache") {
  TEST_CASE("with the cache off a tilted box never rests: it see-saws on one corner") {
    // Fig 4-2..4-4 without the cache: collision detection finds only the deepest point, so each
    // step pushes one corner, the box turns onto the other, and the next step pushes that one.
    WorldSettings settings;
    settings.cache.enabled = false;
    World world = box_on_ground(settings, 2.0, 0.3);
    run(world, 300);
    int sign_changes = 0;
    double last_omega = world.bodies()[1].angular_velocity.z();
    for (int i = 0; i < 300; ++i) {
      world.step();
      CHECK(world.contacts().size() <= 1);
      CHECK_FALSE(at_rest(world.bodies()[1]));
      const double omega = world.bodies()[1].angular_velocity.z();
      if (omega * last_omega < 0.0) ++sign_changes;
      last_omega = omega;
    }
    CHECK(sign_changes > 100);  // still rocking over the last 5 s
  }

  TEST_CASE("with the cache off a flat box rests on one point, under its centre") {
    WorldSettings settings;
    settings.cache.enabled = false;
    World world = box_on_ground(settings, 2.0, 0.0);
    run(world, 600);
    REQUIRE(world.contacts().size() == 1);
    CHECK(std::abs(world.contacts()[0].point.x() - world.bodies()[1].x.x()) < 1e-12);
    // One row carries m g alone (PGS is exact for one row: identity).
    CHECK(world.contacts()[0].lambda_normal == doctest::Approx(g).epsilon(1e-12));
  }

  TEST_CASE("with the cache on the tilted box comes to rest on two corners, each carrying m g / 2") {
    World world = box_on_ground(WorldSettings(), 2.0, 0.3);
    run(world, 600);
    const RigidBody& box = world.bodies()[1];
    CHECK(at_rest(box));
    const std::vector<ContactInfo> contacts = world.contacts();
    REQUIRE(contacts.size() == 2);
    for (const ContactInfo& c : contacts) {
      // the bottom corners, ±h from the centre along the box's x axis
      const Vec3 local = box.rotation.transpose() * (c.point - box.x);
      CHECK(std::abs(local.x()) == doctest::Approx(0.5).epsilon(1e-3));
      // each half the weight: PGS with warm start converges at rest (measured error < 1e-9)
      CHECK(c.lambda_normal == doctest::Approx(g / 2.0).epsilon(1e-6));
    }
  }

  TEST_CASE("the cache warm-starts PGS with last step's λ, and does not with the cache off") {
    for (const bool enabled : {true, false}) {
      WorldSettings settings;
      settings.cache.enabled = enabled;
      World world = box_on_ground(settings, 0.5, 0.0);
      run(world, 10);
      WorldReport before;
      WorldReport after;
      world.step(before);
      world.step(after);
      REQUIRE(before.velocity.solution.lambda.size() == after.velocity.lambda_exp.size());
      if (enabled) {
        CHECK(after.velocity.lambda_exp == before.velocity.solution.lambda);
      } else {
        CHECK(after.velocity.lambda_exp.isZero(0.0));
      }
    }
  }
}

TEST_SUITE("Contact") {
  TEST_CASE("a stack of five boxes stands for 10 s with penetration under 0.01 m") {
    World world(WorldSettings{});
    world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, material(0.6));
    for (int i = 0; i < 5; ++i) world.add_box(1.0, 0.5, 0.5, Vec3(0.0, 0.5 + i, 0.0), 0.0, material(0.6));
    double deepest = 0.0;
    for (int i = 0; i < 600; ++i) {
      world.step();
      for (const ContactInfo& c : world.contacts()) deepest = std::max(deepest, -c.separation);
    }
    // Bound: two slops (2 × 0.005 m); measured 0.002 m.
    CHECK(deepest <= 0.01);
    // The top box stays within 0.02 m of where it was placed (measured 0.0066 m).
    CHECK((world.bodies()[5].x - Vec3(0.0, 4.5, 0.0)).norm() < 0.02);
    for (int b = 1; b <= 5; ++b) CHECK(at_rest(world.bodies()[b]));
  }

  TEST_CASE("a box on a ramp sticks when tan θ < μ and slides at g (sin θ − μ cos θ) when tan θ > μ") {
    struct Ramp {
      double degrees;
      double mu;
    };
    // By `pgs` and by `islands` (chapter 6's default, whose exact solve must not creep either).
    for (const Ramp ramp : {Ramp{10, 0.3}, Ramp{30, 0.3}, Ramp{20, 0.6}, Ramp{40, 0.6}}) {
      for (const std::string method : {"pgs", "islands"}) {
        CAPTURE(ramp.degrees);
        CAPTURE(ramp.mu);
        CAPTURE(method);
        const double theta = ramp.degrees * M_PI / 180.0;
        World world(with_method(WorldSettings{}, method));
        // The ramp: a static box turned by θ; the box sits on its top face, turned the same.
        world.add_static_box(10.0, 0.5, Vec3::Zero(), theta, material(ramp.mu));
        const Vec3 up(-std::sin(theta), std::cos(theta), 0.0);
        const Vec3 down_slope(-std::cos(theta), -std::sin(theta), 0.0);
        world.add_box(1.0, 0.5, 0.5, 1.0 * up, theta, material(ramp.mu));
        run(world, 15);
        const Vec3 x0 = world.bodies()[1].x;
        const double v0 = world.bodies()[1].v.dot(down_slope);
        run(world, 60);
        const double a = world.bodies()[1].v.dot(down_slope) - v0;  // over 1 s
        const double expected = g * (std::sin(theta) - ramp.mu * std::cos(theta));
        if (std::tan(theta) < ramp.mu) {
          // Sticking: no creep (measured 1e-13 m over 1 s).
          CHECK((world.bodies()[1].x - x0).norm() < 1e-9);
        } else {
          CHECK(a == doctest::Approx(expected).epsilon(0.02));  // the 2 %
        }
      }
    }
  }

  TEST_CASE("a resting box: the contact force converges to m g and the contact torque to 0") {
    // Chapter 5, t → ∞: f_c1 → m1 (0, 9.8), τ_c1 → 0, after a tilted landing as in the text;
    // by `pgs` (PGS converged, warm started) and by `islands` (solved exactly).
    for (const std::string method : {"pgs", "islands"}) {
      CAPTURE(method);
      World world = box_on_ground(with_method(WorldSettings(), method), 2.0, 0.3);
      run(world, 599);
      WorldReport report;
      world.step(report);
      const Vec6 wrench = report.velocity.constraint_wrench(1);
      const double mass = world.bodies()[1].mass;
      CHECK(wrench[1] == doctest::Approx(mass * g).epsilon(1e-6));  // converged PGS, warm started
      CHECK(std::abs(wrench[0]) < 1e-6 * mass * g);
      CHECK(std::abs(wrench[5]) < 1e-6 * mass * g);  // N·m about the centre
    }
  }

  TEST_CASE("restitution: above 1 m/s a ball leaves at e times its approach speed, below it stops") {
    for (const double height : {2.0, 0.28}) {
      CAPTURE(height);
      World world(WorldSettings{});
      world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, material(0.6, 0.5));
      world.add_circle(1.0, 0.25, Vec3(0.0, height, 0.0), material(0.6, 0.5));
      double before = 0.0;
      while (world.contacts().empty()) {
        before = world.bodies()[1].v.y();
        world.step();
      }
      const double after = world.bodies()[1].v.y();
      if (-before > 1.0) {
        // One contact row, solved exactly: J V(t+Δt) = −e J V(t) to rounding.
        CHECK(after == doctest::Approx(-0.5 * before).epsilon(1e-9));
      } else {
        CHECK(std::abs(after) < 1e-9);  // approach 0.82 m/s: no bounce
      }
    }
  }

  TEST_CASE("the text's Baumgarte bias also rests the box on two points, with sin(tilt) up to slop / width") {
    WorldSettings settings;
    settings.contact.correction = PositionCorrection::baumgarte;
    World world = box_on_ground(settings, 2.0, 0.3);
    run(world, 600);
    CHECK(at_rest(world.bodies()[1]));
    REQUIRE(world.contacts().size() == 2);
    const double tilt = std::abs(planar_angle(world.bodies()[1].q));
    // Each corner settles anywhere in [0, slop] deep: sin(tilt) is at most slop / 1 m.
    CHECK(tilt <= std::asin(settings.contact.slop) + 1e-9);
    // Split impulse (the default) corrects both corners to the same depth: no tilt.
    World split = box_on_ground(WorldSettings(), 2.0, 0.3);
    run(split, 600);
    CHECK(std::abs(planar_angle(split.bodies()[1].q)) < 1e-5);
  }

  TEST_CASE("a joint's rows follow the contact rows, and both hold") {
    // A box resting on the ground, pinned to the world at its top-right corner.
    World world = box_on_ground(WorldSettings(), 0.5, 0.0);
    const Vec3 pin(0.5, 1.0, 0.0);
    world.add_joint(std::make_unique<RevoluteJoint>(Anchor{lamina::world, pin},
                                                    anchor_at(world.bodies(), 1, pin)));
    run(world, 120);
    WorldReport report;
    world.step(report);
    // the row map: the pair's two contact rows, then the manifold's one friction row (pgs,
    // contact_rows.h), then the joint's two
    REQUIRE(report.velocity.mlcp.row_count() == 5);
    REQUIRE(report.pairs.size() == 1);
    const ContactPair& pair = report.pairs[0];
    REQUIRE(pair.count == 2);
    CHECK(pair.contacts[0].row == 0);
    CHECK(pair.contacts[1].row == 1);
    CHECK(pair.contacts[0].friction_rows[0] == 2);
    CHECK(pair.contacts[1].friction_rows[0] == 2);
    CHECK(pair.rows.first == 0);
    CHECK(pair.rows.count == 3);
    REQUIRE(report.joints.size() == 1);
    CHECK(report.joints[0].first == 3);
    CHECK(report.joints[0].count == 2);
    const RigidBody& box = world.bodies()[1];
    CHECK((box.x + box.rotation * Vec3(0.5, 0.5, 0.0) - pin).norm() < 1e-3);
    CHECK(at_rest(box));
  }
}

TEST_SUITE("World") {
  TEST_CASE("a heap of boxes and discs stays exactly in the plane") {
    World world = heap(WorldSettings());
    for (int i = 0; i < 300; ++i) {
      world.step();
      for (const RigidBody& body : world.bodies()) REQUIRE(out_of_plane(body) == 0.0);
    }
  }

  TEST_CASE("the text's second tangent u2 = z gets λ = 0 exactly and changes nothing") {
    // u2's row acts on v_z, ω_x, ω_y only, which are zero, and no in-plane row reaches them:
    // J B is block diagonal and η = 0 there, so PGS leaves λ_u2 at exactly 0.
    WorldSettings with_u2;
    with_u2.contact.out_of_plane_friction = true;
    World a = heap(WorldSettings());
    World b = heap(with_u2);
    int u2_rows = 0;
    for (int i = 0; i < 200; ++i) {
      a.step();
      WorldReport report;
      b.step(report);
      for (const ContactPair& pair : report.pairs) {
        for (int k = 0; k < pair.count; ++k) {
          const int u2 = pair.contacts[k].friction_rows[1];  // the row along u2 = z, or −1
          if (u2 < 0) continue;
          ++u2_rows;
          REQUIRE(report.velocity.solution.lambda[u2] == 0.0);
        }
      }
    }
    CHECK(u2_rows > 0);
    check_identical(a, b);
  }

  TEST_CASE("two identical worlds stepped side by side stay bit-identical") {
    World a = heap(WorldSettings());
    World b = heap(WorldSettings());
    for (int i = 0; i < 200; ++i) {
      a.step();
      b.step();
    }
    check_identical(a, b);
  }

  TEST_CASE("a step that fills a report moves the bodies bit for bit as one that does not") {
    World plain = heap(WorldSettings());
    World reported = heap(WorldSettings());
    for (int i = 0; i < 100; ++i) {
      plain.step();
      WorldReport report;
      reported.step(report);
    }
    check_identical(plain, reported);
  }

  TEST_CASE("a report records every PGS sweep and the contacts in row order") {
    World world = box_on_ground(WorldSettings(), 0.5, 0.0);
    run(world, 5);
    WorldReport report;
    world.step(report);
    CHECK(report.velocity.solution.residuals.size() == 10);  // the default 10 sweeps
    CHECK(report.contacts().size() == 2);
    CHECK(report.velocity.mlcp.row_count() == 3);  // two contact rows, the manifold's friction row
    CHECK(report.position.mlcp.row_count() == 2);  // split impulse: one row per contact
    CHECK(report.time == doctest::Approx(5.0 / 60.0).epsilon(1e-12));
  }

  TEST_CASE("a kept point is re-anchored once its anchors slide apart by more than drift_limit") {
    // A box's corner on the ground's top face (y = 0), found fresh, then the box slid along x
    // by s with no fresh point: the ground's anchor stays put for s below drift_limit and moves
    // under the corner (x = −0.5 + s) above it. 10 % on either side of the limit, so the test
    // does not depend on how the limit is compared.
    const std::vector<Shape> shapes{Shape::box(5.0, 0.5), Shape::box(0.5, 0.5)};
    const std::vector<Material> materials(2);
    CacheSettings settings;
    for (const double share : {0.9, 1.1}) {
      CAPTURE(share);
      const double s = share * settings.drift_limit;
      ContactCache cache;
      std::vector<Pose2> poses{Pose2{Vec2(0.0, -0.5)}, Pose2{Vec2(0.0, 0.5)}};
      Collision corner;
      corner.point = Vec2(-0.5, 0.0);  // the box's corner, depth 0, on the ground's face
      cache.update({FreshCollision{BodyPair{0, 1}, corner}}, {}, poses, shapes, materials, settings);
      REQUIRE(cache.pairs().size() == 1);
      CHECK(cache.pairs()[0].contacts[0].anchor[0] == Vec2(-0.5, 0.5));  // ground frame
      poses[1].x.x() += s;
      cache.update({}, {}, poses, shapes, materials, settings);
      REQUIRE(cache.pairs().size() == 1);
      const Contact& kept = cache.pairs()[0].contacts[0];
      CHECK(kept.origin == ContactOrigin::kept);
      // re-anchored: −0.5 + s, exact to a rounding of the sum
      CHECK(kept.anchor[0].x() == doctest::Approx(share > 1.0 ? -0.5 + s : -0.5).epsilon(1e-15));
      CHECK(kept.anchor[0].y() == 0.5);
    }
  }

  TEST_CASE("bad settings and bodies out of the plane are refused with a message") {
    WorldSettings bad;
    bad.step.dt = 0.0;
    CHECK_THROWS_AS(World{bad}, std::invalid_argument);
    WorldSettings bad_beta;
    bad_beta.step.beta = 1.5;
    CHECK_THROWS_AS(World{bad_beta}, std::invalid_argument);
    World world(WorldSettings{});
    RigidBody lifted = box_body(1.0, 0.5, 0.5, Vec3(0.0, 1.0, 0.1));
    CHECK_THROWS_AS(world.add_body(lifted, Shape::box(0.5, 0.5)), std::invalid_argument);
    CHECK_THROWS_AS(world.add_box(1.0, 0.5, 0.5, Vec3::Zero(), 0.0, material(-0.1)),
                    std::invalid_argument);
    CHECK_THROWS_AS(validate(Shape::circle(0.0)), std::invalid_argument);
  }
}
