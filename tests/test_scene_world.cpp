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
}
