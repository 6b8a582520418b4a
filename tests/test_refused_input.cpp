// Input that cannot be simulated is refused before the first step, with one line naming it
// (issue 9): a scene value just past the end of its range, a joint that can move nothing, a rod
// of length 0, World settings and bodies out of range; and a state gone non-finite is seen.
// Scenes lie in the x–y plane, y up; the ground is a static box whose top is y = 0.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "constraints/jacobian_rows.h"
#include "constraints/revolute_joint.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_limits.h"
#include "scene/scene_world.h"
#include "support/watched_scene.h"

using namespace lamina;

namespace {

// A pendulum hung from a static post that a second joint ties to the ground.
Scene post_tied_to_ground() {
  Scene s = builtin_scene("pendulum");
  s.bodies.push_back(ground());
  JointDescription tie;
  tie.bodies = {"ground", "pivot"};
  tie.anchor = {0.0, 2.0};
  s.joints.push_back(tie);
  return s;
}

}  // namespace

TEST_SUITE("RefusedInput") {
  TEST_CASE("a value just past either end of a scene limit is refused with its path and range") {
    // Each case edits one value of a valid scene (ground, box, disc, capsule, a revolute and a
    // distance joint) to the next double beyond an end of its range; the ends themselves are accepted.
    namespace limits = scene_limits;
    struct Limit {
      const char* path;
      limits::Range<double> range;
      std::function<void(Scene&, double)> edit;
    };
    const std::vector<Limit> cases = {
        {"dt", limits::dt, [](Scene& s, double v) { s.step.dt = v; }},
        {"beta", limits::beta, [](Scene& s, double v) { s.step.beta = v; }},
        {"gravity[0]", limits::gravity, [](Scene& s, double v) { s.step.gravity[0] = v; }},
        {"gravity[1]", limits::gravity, [](Scene& s, double v) { s.step.gravity[1] = v; }},
        {"bodies[1].position[0]", limits::coordinate,
         [](Scene& s, double v) { s.bodies[1].position[0] = v; }},
        {"bodies[1].position[1]", limits::coordinate,
         [](Scene& s, double v) { s.bodies[1].position[1] = v; }},
        {"bodies[1].angle", limits::angle, [](Scene& s, double v) { s.bodies[1].angle = v; }},
        {"bodies[1].shape.half_extents[0]", limits::size,
         [](Scene& s, double v) { s.bodies[1].shape.half_extents[0] = v; }},
        {"bodies[1].shape.half_extents[1]", limits::size,
         [](Scene& s, double v) { s.bodies[1].shape.half_extents[1] = v; }},
        {"bodies[2].shape.radius", limits::size,
         [](Scene& s, double v) { s.bodies[2].shape.radius = v; }},
        {"bodies[3].shape.radius", limits::size,
         [](Scene& s, double v) { s.bodies[3].shape.radius = v; }},
        {"bodies[3].shape.length", limits::capsule_length,
         [](Scene& s, double v) { s.bodies[3].shape.length = v; }},
        {"bodies[1].density", limits::density, [](Scene& s, double v) { s.bodies[1].density = v; }},
        {"bodies[1].friction", limits::friction,
         [](Scene& s, double v) { s.bodies[1].friction = v; }},
        {"bodies[1].restitution", limits::restitution,
         [](Scene& s, double v) { s.bodies[1].restitution = v; }},
        {"bodies[1].velocity[0]", limits::speed,
         [](Scene& s, double v) { s.bodies[1].velocity[0] = v; }},
        {"bodies[1].velocity[1]", limits::speed,
         [](Scene& s, double v) { s.bodies[1].velocity[1] = v; }},
        {"bodies[1].angular_velocity", limits::angular_speed,
         [](Scene& s, double v) { s.bodies[1].angular_velocity = v; }},
        {"joints[0].anchor[1]", limits::coordinate,
         [](Scene& s, double v) { s.joints[0].anchor[1] = v; }},
        {"joints[1].anchors[1][0]", limits::coordinate,
         [](Scene& s, double v) { s.joints[1].anchors[1][0] = v; }},
    };
    Scene valid = stack(1);
    valid.bodies.push_back(circle("disc", {3.0, 0.5}, 0.5));
    BodyDescription rod_shaped = circle("capsule", {-3.0, 0.5}, 0.5);
    rod_shaped.shape.type = ShapeType::capsule;
    rod_shaped.shape.length = 1.0;
    valid.bodies.push_back(rod_shaped);
    JointDescription pin;
    pin.bodies = {"ground", "box0"};
    pin.anchor = {0.0, 1.0};
    JointDescription rod;
    rod.type = JointType::distance;
    rod.bodies = {"ground", "disc"};
    rod.anchors = {Vec2{3.0, 3.0}, Vec2{3.0, 0.5}};
    valid.joints = {pin, rod};
    REQUIRE(refusal(valid) == "(accepted)");
    const double inf = std::numeric_limits<double>::infinity();
    for (const Limit& limit : cases) {
      CAPTURE(limit.path);
      for (double value :
           {std::nextafter(limit.range.low, -inf), std::nextafter(limit.range.high, inf)}) {
        CAPTURE(value);
        Scene scene = valid;
        limit.edit(scene, value);
        const std::string message = refusal(scene);
        CHECK(message.rfind(std::string("edited.json: ") + limit.path + ": must be in [", 0) == 0);
      }
      for (double value : {limit.range.low, limit.range.high}) {
        CAPTURE(value);
        Scene scene = valid;
        limit.edit(scene, value);
        CHECK(refusal(scene) == "(accepted)");
      }
    }
  }

  TEST_CASE("a joint between static bodies, or a rod of length 0, is refused before any step") {
    // A joint's rows on static bodies alone have d = J M⁻¹ Jᵀ = 0, and PGS divides by d. Before
    // this guard, a pendulum hung from a post that a second joint tied to the ground went
    // non-finite in its first step: the tie's λ = −∞ made the post's B λ = 0 · ∞, which the
    // rod's row then read.
    // The reader checks a joint's form; its physics (a body that moves, a rod of some length) is
    // the engine's, and build_world reports it with the joint's JSON path (scene_json.cpp).
    const Scene tied = post_tied_to_ground();
    CHECK(refusal(tied) == "(accepted)");
    CHECK_THROWS_WITH_AS(build_world(tied, world_settings(tied)),
                         "joints[1] (\"ground\", \"pivot\"): joint 1 joins only static bodies (or the "
                         "world): it can move nothing",
                         std::invalid_argument);
    World posts;
    const int a = posts.add_static_box(1.0, 1.0, Vec3(0.0, 0.0, 0.0));
    const int b = posts.add_static_box(1.0, 1.0, Vec3(3.0, 0.0, 0.0));
    const Vec3 pin(1.5, 0.0, 0.0);
    CHECK_THROWS_AS(posts.add_joint(std::make_unique<RevoluteJoint>(
                        anchor_at(posts.bodies(), a, pin), anchor_at(posts.bodies(), b, pin))),
                    std::invalid_argument);
    CHECK_THROWS_AS(posts.add_joint(std::make_unique<RevoluteJoint>(
                        anchor_at(posts.bodies(), a, pin), anchor_at(posts.bodies(), world, pin))),
                    std::invalid_argument);

    Scene rod = builtin_scene("pendulum");
    rod.joints[0].anchors[0] = rod.joints[0].anchors[1];
    CHECK(refusal(rod) == "(accepted)");
    CHECK_THROWS_WITH_AS(build_world(rod, world_settings(rod)),
                         "joints[0] (\"pivot\", \"bob\"): distance constraint: the rod's two ends "
                         "coincide or its length L is not finite and positive: a rod needs a length "
                         "(a revolute joint pins two bodies at one point)",
                         std::invalid_argument);
  }

  TEST_CASE("World settings and bodies out of range are refused; 0 sweeps are accepted") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (double dt : {0.0, -1e-3, nan, inf}) {
      CAPTURE(dt);
      WorldSettings settings;
      settings.step.dt = dt;
      CHECK_THROWS_AS(World{settings}, std::invalid_argument);
    }
    for (const Vec3& gravity : {Vec3(nan, -9.8, 0.0), Vec3(0.0, inf, 0.0), Vec3(0.0, -9.8, 1.0)}) {
      WorldSettings settings;
      settings.step.gravity = gravity;
      CHECK_THROWS_AS(World{settings}, std::invalid_argument);
    }
    WorldSettings settings;
    settings.step.iterations = -1;
    CHECK_THROWS_AS(World{settings}, std::invalid_argument);
    settings.step.iterations = 0;
    CHECK_NOTHROW(World{settings});

    World bodies;
    RigidBody body = box_body(1.0, 0.5, 0.5, Vec3(0.0, 1.0, 0.0));
    body.v.x() = nan;
    CHECK_THROWS_WITH_AS(bodies.add_body(body, Shape::box(0.5, 0.5)),
                         "body 0 has a position, orientation or velocity that is not finite",
                         std::invalid_argument);
    body.v.x() = 0.0;
    body.angular_velocity.z() = inf;
    CHECK_THROWS_AS(bodies.add_body(body, Shape::box(0.5, 0.5)), std::invalid_argument);
  }

  TEST_CASE("a state with a NaN or an infinity anywhere is seen as not finite") {
    // has_finite_state is what stops a run whose step went non-finite (`lamina run`).
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const RigidBody sound = box_body(1.0, 0.5, 0.5, Vec3(0.0, 1.0, 0.0));
    CHECK(sound.has_finite_state());
    for (int part = 0; part < 4; ++part) {
      for (double bad : {nan, inf, -inf}) {
        CAPTURE(part);
        RigidBody b = sound;
        if (part == 0) b.x.y() = bad;
        if (part == 1) b.q.w() = bad;
        if (part == 2) b.v.x() = bad;
        if (part == 3) b.angular_velocity.z() = bad;
        CHECK_FALSE(b.has_finite_state());
      }
    }
  }
}
