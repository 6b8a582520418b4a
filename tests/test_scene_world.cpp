// Scenes become worlds: every built-in scene runs, and a scene builds exactly the world that
// the same bodies added by hand would.
#include <doctest/doctest.h>

#include <cmath>

#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

using namespace lamina;

TEST_SUITE("SceneWorld") {
  TEST_CASE("every built-in scene runs 120 steps with finite, planar states") {
    for (const BuiltinScene& entry : builtin_scene_list()) {
      CAPTURE(entry.name);
      const Scene scene = builtin_scene(entry.name);
      World world = build_world(scene, world_settings(scene));
      REQUIRE(world.bodies().size() == scene.bodies.size());
      for (int step = 0; step < 120; ++step) world.step();
      for (const RigidBody& body : world.bodies()) {
        CHECK(body.x.allFinite());
        CHECK(body.v.allFinite());
        // Planar scenes stay exactly planar (no tolerance: the 3D core must not leak).
        CHECK(body.x.z() == 0.0);
        CHECK(body.angular_velocity.x() == 0.0);
        CHECK(body.angular_velocity.y() == 0.0);
      }
    }
  }

  TEST_CASE("a scene builds the same world as the same bodies added by hand") {
    // Identity: both paths must give bit-identical states after 200 steps.
    const Scene scene = builtin_scene("box-on-ground-tilted");
    World from_scene = build_world(scene, world_settings(scene));
    World by_hand(world_settings(scene));
    by_hand.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, Material{0.6, 0.0});
    by_hand.add_box(1.0, 0.5, 0.5, Vec3(0.0, 2.0, 0.0), 0.3, Material{0.6, 0.0});
    for (int step = 0; step < 200; ++step) {
      from_scene.step();
      by_hand.step();
    }
    CHECK(from_scene.bodies()[1].x == by_hand.bodies()[1].x);
    CHECK(from_scene.bodies()[1].q.coeffs() == by_hand.bodies()[1].q.coeffs());
  }

  TEST_CASE("bodies joined by a joint never collide with each other") {
    // The chain's links overlap at their pins; Box2D's default (collideConnected = false) is
    // that such pairs make no contact, and Lamina follows it.
    const Scene scene = builtin_scene("chain");
    World world = build_world(scene, world_settings(scene));
    for (int step = 0; step < 60; ++step) {
      world.step();
      for (const ContactInfo& contact : world.contacts()) {
        const bool links = contact.bodies.first >= 2 && contact.bodies.second >= 2;
        const bool anchor_and_first_link = contact.bodies.first == 1 && contact.bodies.second == 2;
        CHECK_FALSE((links && contact.bodies.second == contact.bodies.first + 1));
        CHECK_FALSE(anchor_and_first_link);
      }
    }
  }

  TEST_CASE("a pendulum scene keeps its rod length") {
    // Distance constraint from the scene's anchors: |x_bob − pivot| stays 2 m within the drift
    // bound of chapter 3 (β = 0.2, Δt = 1/60: a few mm over one swing).
    const Scene scene = builtin_scene("pendulum");
    World world = build_world(scene, world_settings(scene));
    double worst = 0.0;
    for (int step = 0; step < 180; ++step) {
      world.step();
      worst = std::max(worst, std::abs((world.bodies()[1].x - Vec3(0.0, 3.0, 0.0)).norm() - 2.0));
    }
    CHECK(worst < 0.02);
  }

  TEST_CASE("a polygon's position is its vertices' origin; its centre of mass is their centroid") {
    // A right triangle with legs 3 (x) and 1.5 (y) from its vertices' origin: centroid (1, 0.5)
    // (mass_properties.h), placed at (2, 1) turned by 0.4 rad.
    Scene scene = builtin_scene("box-on-ground");
    BodyDescription& piece = scene.bodies[1];
    piece.shape.type = ShapeType::polygon;
    piece.shape.vertices = {{0.0, 0.0}, {3.0, 0.0}, {0.0, 1.5}};
    piece.position = {2.0, 5.0};
    piece.angle = 0.4;
    piece.density = 2.0;
    const World world = build_world(scene, world_settings(scene));
    const RigidBody& body = world.bodies()[1];
    const Vec2 c(1.0, 0.5);
    const Vec2 turned(std::cos(0.4) * c.x() - std::sin(0.4) * c.y(),
                      std::sin(0.4) * c.x() + std::cos(0.4) * c.y());
    // a few roundings of exact inputs
    CHECK((body.x.head<2>() - (piece.position + turned)).norm() <= 1e-12);
    CHECK(body.x.z() == 0.0);
    CHECK(body.mass == doctest::Approx(2.0 * 3.0 * 1.5 / 2.0).epsilon(1e-12));  // ρ A
    // I_zz = ρ (J_xx + J_yy) = ρ (a³b + ab³)/36 for the right triangle about its centroid
    CHECK(body.inertia_world()(2, 2) ==
          doctest::Approx(2.0 * (27.0 * 1.5 + 3.0 * 3.375) / 36.0).epsilon(1e-12));
    // the World's shape: the same vertices about the centroid
    const Shape& shape = world.shape(1);
    REQUIRE(shape.vertex_count == 3);
    CHECK((shape.vertices[0] - Vec2(-1.0, -0.5)).norm() <= 1e-12);
    CHECK((shape.vertices[1] - Vec2(2.0, -0.5)).norm() <= 1e-12);
    CHECK((shape.vertices[2] - Vec2(-1.0, 1.0)).norm() <= 1e-12);
  }

  TEST_CASE("a tumbling polygon and capsules stay exactly planar though a polygon's I0 has I_xy") {
    // A scalene triangle's body-frame inertia has a product of inertia; R I0 Rᵀ about z keeps
    // its z row (0, 0, I_zz), so ω stays along z exactly.
    Scene triangle = builtin_scene("box-on-ground-tilted");
    triangle.bodies[1].shape.type = ShapeType::polygon;
    triangle.bodies[1].shape.vertices = {{0.0, 0.0}, {1.0, 0.0}, {0.2, 0.7}};
    triangle.bodies[1].angular_velocity = 3.0;
    for (const Scene& scene : {triangle, builtin_scene("wedge-ramp"), builtin_scene("capsule-pile")}) {
      CAPTURE(scene.name);
      World world = build_world(scene, world_settings(scene));
      for (int step = 0; step < 300; ++step) world.step();
      for (const RigidBody& body : world.bodies()) {
        CHECK(body.x.z() == 0.0);
        CHECK(body.v.z() == 0.0);
        CHECK(body.angular_velocity.x() == 0.0);
        CHECK(body.angular_velocity.y() == 0.0);
      }
    }
  }
}
