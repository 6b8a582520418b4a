// The chapter-3 constraints from scene files: an angle limit (eq. 3-17..3-22 for an angle) and
// an incline, Fig 3-1 (eq. 3-1..3-4, 3-14) or Fig 3-2 (eq. 3-17..3-22). They are read, written
// back unchanged, built into a World that moves as the text says, and bad ones are refused
// with one line naming the JSON path. Scenes lie in the x–y plane, y up.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/scene_json.h"
#include "scene/scene_world.h"
#include "scene/shortest_number.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, the scene files' default, in m/s²

// What refuses the scene, as `lamina check` says it: the reader (form and ranges), or the engine
// when the World is built (physical rules), led by the JSON path; "(accepted)" for neither.
std::string refusal(const std::string& json_text) {
  try {
    const Scene scene = parse_scene(json_text, "joints.json");
    build_world(scene, world_settings(scene));
  } catch (const SceneError& e) {
    return e.what();
  } catch (const std::invalid_argument& e) {
    return std::string("joints.json: ") + e.what();
  }
  return "(accepted)";
}

// A static pivot, the chapter-3 tutorial's bar pinned to it at (0, 0) and lying along −x from
// it (a mirror of the built-in angle-limit scene, so that it swings to positive θ), a static
// ground and a free box; `joints` is the scene's joint list.
std::string bar_scene(const std::string& joints) {
  return R"({"name": "bar", "bodies": [
    {"name": "pivot", "shape": {"type": "box", "half_extents": [0.1, 0.1]}, "static": true},
    {"name": "bar", "shape": {"type": "box", "half_extents": [0.6, 0.05]}, "position": [-0.6, 0],
     "density": 8.333333333333334},
    {"name": "ground", "shape": {"type": "box", "half_extents": [20, 0.5]}, "position": [0, -5],
     "static": true},
    {"name": "box", "shape": {"type": "box", "half_extents": [0.4, 0.25]}, "position": [3, 2],
     "density": 5}],
  "joints": [)" + joints + "]}";
}

// θ of the second body relative to the first, in (−π, π] (angle_limit.h).
double relative_angle(const World& world, int a, int b) {
  return planar_angle(world.bodies()[a].q.conjugate() * world.bodies()[b].q);
}

// The smallest and largest θ of body 1 relative to body 0 over `steps` steps, and the first
// step after which θ came within `near` of `target`, or −1.
struct Swing {
  double low = INFINITY;
  double high = -INFINITY;
  int reached = -1;
};
Swing swing(const Scene& scene, int steps, double target, double near) {
  World world = build_world(scene, world_settings(scene));
  Swing s;
  for (int k = 0; k < steps; ++k) {
    world.step();
    const double theta = relative_angle(world, 0, 1);
    s.low = std::min(s.low, theta);
    s.high = std::max(s.high, theta);
    if (s.reached < 0 && std::abs(theta - target) <= near) s.reached = k;
  }
  return s;
}

// The scene without its angle limits: the same bar, free to swing.
Scene without_limits(Scene scene) {
  const auto is_limit = [](const JointDescription& j) { return j.type == JointType::angle_limit; };
  scene.joints.erase(std::remove_if(scene.joints.begin(), scene.joints.end(), is_limit), scene.joints.end());
  return scene;
}

}  // namespace

TEST_SUITE("SceneJoints") {
  TEST_CASE("an angle limit and an incline survive a read, a write and a read unchanged") {
    // Identity: every field read back bit for bit, and the text written twice is the same text.
    // The numbers are ones a decimal writer could round: 0.1 + 0.2 = 0.30000000000000004.
    const std::string text = bar_scene(R"(
      {"type": "revolute", "bodies": ["pivot", "bar"], "anchor": [0, 0]},
      {"type": "angle_limit", "bodies": ["pivot", "bar"], "lower": -0.30000000000000004, "upper": 2.0707963267948966},
      {"type": "angle_limit", "bodies": ["ground", "box"], "upper": 0.1},
      {"type": "incline", "body": "box", "point": [0.125, 3.8165063509461097], "normal": [0.5, 0.8660254037844386]},
      {"type": "incline", "body": "bar", "point": [1e-7, -3], "normal": [0, 1], "one_sided": true})");
    const Scene first = parse_scene(text, "joints.json");
    const std::string written = scene_to_json(first);
    const Scene second = parse_scene(written, "written.json");
    CHECK(scene_to_json(second) == written);
    REQUIRE(second.joints.size() == 5);
    for (size_t i = 0; i < first.joints.size(); ++i) {
      CAPTURE(i);
      const JointDescription& a = first.joints[i];
      const JointDescription& b = second.joints[i];
      CHECK(a.type == b.type);
      CHECK(a.bodies == b.bodies);
      CHECK(a.lower == b.lower);
      CHECK(a.upper == b.upper);
      CHECK(a.body == b.body);
      CHECK(a.point == b.point);
      CHECK(a.normal == b.normal);
      CHECK(a.one_sided == b.one_sided);
    }
    // What the file said, read as written: the sides given, and one_sided's default false.
    CHECK(second.joints[1].lower == -0.30000000000000004);
    CHECK(second.joints[1].upper == 2.0707963267948966);
    CHECK_FALSE(second.joints[2].lower.has_value());
    CHECK(second.joints[2].upper == 0.1);
    CHECK(second.joints[3].type == JointType::incline);
    CHECK(second.joints[3].body == "box");
    CHECK(second.joints[3].normal == Vec2(0.5, 0.8660254037844386));
    CHECK_FALSE(second.joints[3].one_sided);
    CHECK(second.joints[4].one_sided);
    CHECK(second.joints[4].point == Vec2(1e-7, -3.0));
  }

  TEST_CASE("Fig 3-1 from a file: a box held on a frictionless incline slides with g sin θ") {
    for (double degrees : {10.0, 30.0, 45.0, 60.0}) {
      CAPTURE(degrees);
      const double theta = degrees * M_PI / 180.0;
      const Vec2 normal(std::sin(theta), std::cos(theta));      // N
      const Vec2 downhill(std::cos(theta), -std::sin(theta));   // along the line, down
      const std::string n = "[" + shortest_number(normal.x()) + ", " + shortest_number(normal.y()) + "]";
      const Scene scene = parse_scene(R"({"bodies": [
          {"name": "box", "shape": {"type": "box", "half_extents": [0.4, 0.25]}, "position": [0, 1],
           "density": 5}],
        "joints": [{"type": "incline", "body": "box", "point": [0, 1], "normal": )" + n + "}]}",
                                      "incline.json");
      World world = build_world(scene, world_settings(scene));
      const double dt = scene.step.dt;
      for (int k = 0; k < 60; ++k) {
        const double before = world.bodies()[0].v.head<2>().dot(downhill);
        WorldReport report;
        world.step(report);
        const RigidBody& box = world.bodies()[0];
        // analytic (eq. 3-3, 3-4): a = g sin θ along the line and λ = m g cos θ (m = 2 kg); the
        // one row is solved exactly by the first PGS sweep, so 1e-9 relative is rounding only
        const double a = (box.v.head<2>().dot(downhill) - before) / dt;
        CHECK(std::abs(a - g * std::sin(theta)) <= 1e-9 * g * std::sin(theta));
        const double lambda = report.velocity.solution.lambda[report.joints[0].first];
        CHECK(std::abs(lambda - 2.0 * g * std::cos(theta)) <= 1e-9 * 2.0 * g * std::cos(theta));
        // eq. 3-1: the centre stays on the line, C = (x − p)·N at rounding level (1e-12 m)
        CHECK(std::abs((box.x.head<2>() - Vec2(0.0, 1.0)).dot(normal)) <= 1e-12);
      }
    }
  }

  TEST_CASE("thrown off the line, a one-sided incline lets the box go (Fig 3-2), a bilateral one holds it") {
    // A 2 kg box on a 30° line, thrown off it along N at 3 m/s. Bilateral (Fig 3-1, eq. 3-14):
    // v·N = 0 after every step, C = (x − p)·N at rounding level (1e-12 m). One-sided (Fig 3-2,
    // eq. 3-17..3-22): leaving needs no force, λ = 0, and the box flies as a projectile, C after
    // step k = Δt Σ_{i=1..k} (3 − i g cos θ Δt) (chapter 2's step, analytic; 1e-12 m rounding).
    // Stepped by `pgs`: `islands` takes a jointed body in 8 substeps, whose flight is another sum.
    const double theta = M_PI / 6.0;
    const Vec2 normal(0.5, std::sqrt(3.0) / 2.0);  // (sin θ, cos θ)
    for (const bool one_sided : {false, true}) {
      CAPTURE(one_sided);
      const Vec2 v = 3.0 * normal;
      const Scene scene = parse_scene(R"({"solver": "pgs", "bodies": [
          {"name": "box", "shape": {"type": "box", "half_extents": [0.4, 0.25]}, "position": [0, 1],
           "density": 5, "velocity": [)" + shortest_number(v.x()) + ", " + shortest_number(v.y()) + R"(]}],
        "joints": [{"type": "incline", "body": "box", "point": [0, 1], "normal": [0.5, )" +
                                          shortest_number(normal.y()) + "], \"one_sided\": " +
                                          (one_sided ? "true" : "false") + "}]}",
                                      "thrown.json");
      World world = build_world(scene, world_settings(scene));
      const double dt = scene.step.dt;
      double expected = 0.0;  // C of the free flight, in m
      for (int k = 1; k <= 20; ++k) {
        world.step();
        expected += dt * (3.0 - k * g * std::cos(theta) * dt);
        const double C = (world.bodies()[0].x.head<2>() - Vec2(0.0, 1.0)).dot(normal);
        CHECK(std::abs(C - (one_sided ? expected : 0.0)) <= 1e-12);
      }
    }
  }

  TEST_CASE("an angle limit stops the bar at θ_L; the same bar without it swings past") {
    // The built-in scene: released level (θ = 0), the bar swings down and the lower limit
    // θ_L = −π/2 − 0.5 stops it within its first second (measured: at step 37, t = 0.63 s).
    // The limit's ζ = −C/Δt (eq. 3-18) lets the gap close exactly within a step,
    // then −β C/Δt (eq. 3-14) pushes back what the pin's rows and the limit's, solved together
    // by 10 PGS sweeps, leave past it: measured 0 (θ stops at θ_L to the last bit), bound 1e-3
    // rad, 1/500 of the 0.5 rad margin below hanging.
    const Scene scene = builtin_scene("angle-limit");
    const double limit = -M_PI / 2.0 - 0.5;
    const double baumgarte = 1e-3;  // rad, the bound above
    const Swing limited = swing(scene, 300, limit, baumgarte);
    CHECK(limited.low >= limit - baumgarte);
    CHECK(limited.reached >= 0);
    CHECK(limited.reached < 60);  // active within the first second (60 steps of 1/60 s)
    // Unlimited, the bar keeps its energy and swings on towards θ = −π, level on the other side
    // (measured: −3.12 rad): it passes θ_L by 1.05 rad, far more than the Baumgarte bound.
    const Swing unlimited = swing(without_limits(scene), 300, limit, baumgarte);
    CHECK(unlimited.low < limit - 0.5);
  }

  TEST_CASE("a two-sided angle limit from a file holds its upper side; unlimited the bar passes") {
    // The mirror of the built-in scene: the bar lies along −x from its pin and swings to positive
    // θ; upper = π/2 + 0.5 stops it as lower stops the built-in one, and lower = −0.3 (the
    // bar never swings up past level) is given so that both rows are built. Bound as above.
    const double upper = M_PI / 2.0 + 0.5;
    const Scene scene = parse_scene(bar_scene(R"(
      {"type": "revolute", "bodies": ["pivot", "bar"], "anchor": [0, 0]},
      {"type": "angle_limit", "bodies": ["pivot", "bar"], "lower": -0.3, "upper": )" +
                                              shortest_number(upper) + "}"),
                                    "two-sided.json");
    REQUIRE(build_world(scene, world_settings(scene)).joint_count() == 3);  // pin, lower, upper
    const double baumgarte = 1e-3;  // rad
    const Swing limited = swing(scene, 300, upper, baumgarte);
    CHECK(limited.high <= upper + baumgarte);
    CHECK(limited.low >= -0.3 - baumgarte);
    CHECK(limited.reached >= 0);
    const Swing unlimited = swing(without_limits(scene), 300, upper, baumgarte);
    CHECK(unlimited.high > upper + 0.5);
  }

  TEST_CASE("a bad angle limit or incline is refused with one line naming its JSON path") {
    // Exact messages, each the whole line `lamina check` prints after "lamina: " (for −π, the
    // start of it: the engine's message ends with the limit rounded to six digits).
    const std::string pin = R"({"type": "revolute", "bodies": ["pivot", "bar"], "anchor": [0, 0]}, )";
    const auto incline = [](const std::string& normal) {
      return R"({"type": "incline", "body": "box", "point": [3, 2], "normal": )" + normal + "}";
    };
    CHECK(refusal(bar_scene(incline("[0.6, 0.8]"))) == "(accepted)");
    // The reader: a component of N beyond ±1.
    CHECK(refusal(bar_scene(incline("[2, 0]"))) == "joints.json: joints[0].normal[0]: must be in [-1, 1], got 2");
    // The engine (InclineConstraint): N not of unit length, or zero; led by the joint's path.
    CHECK(refusal(bar_scene(incline("[0.5, 0.866]"))) ==
          "joints.json: joints[0] (\"box\"): incline constraint: normal N must be a unit vector, |N| = 0.999978");
    CHECK(refusal(bar_scene(incline("[0, 0]"))) ==
          "joints.json: joints[0] (\"box\"): incline constraint: normal N must be a unit vector, |N| = 0.000000");
    // A missing body, a body the scene does not have, a static body.
    CHECK(refusal(bar_scene(R"({"type": "incline", "point": [3, 2], "normal": [0, 1]})")) ==
          "joints.json: joints[0].body: is missing");
    CHECK(refusal(bar_scene(R"({"type": "incline", "body": "crate", "point": [3, 2], "normal": [0, 1]})")) ==
          "joints.json: joints[0].body: no body is named \"crate\"");
    CHECK(refusal(bar_scene(R"({"type": "incline", "body": "ground", "point": [3, 2], "normal": [0, 1]})")) ==
          "joints.json: joints[0] (\"ground\"): joint 0 joins only static bodies (or the world): it can move "
          "nothing");
    CHECK(refusal(bar_scene(pin + R"({"type": "angle_limit", "upper": 1})")) ==
          "joints.json: joints[1].bodies: is missing");
    // Unknown keys, a key of another joint type among them, and a key given twice.
    CHECK(refusal(bar_scene(R"({"type": "incline", "body": "box", "point": [3, 2], "normal": [0, 1],
                               "friction": 0})")) ==
          "joints.json: joints[0].friction: unknown key (allowed: body, normal, one_sided, point, type)");
    CHECK(refusal(bar_scene(pin + R"({"type": "angle_limit", "bodies": ["pivot", "bar"], "anchor": [0, 0],
                                     "upper": 1})")) ==
          "joints.json: joints[1].anchor: unknown key (allowed: bodies, lower, type, upper)");
    CHECK(refusal(bar_scene(pin + R"({"type": "angle_limit", "bodies": ["pivot", "bar"], "lower": 1,
                                     "lower": 2})")) ==
          "joints.json: joints[1].lower: duplicate key: the object has \"lower\" already");
    CHECK(refusal(bar_scene(R"({"type": "incline", "body": "box", "point": [3, 2], "normal": [0, 1],
                               "one_sided": 1})")) ==
          "joints.json: joints[0].one_sided: must be true or false, got number 1");
    // An angle limit's sides: lower above upper, none at all, beyond ±π, or −π itself.
    CHECK(refusal(bar_scene(pin + R"({"type": "angle_limit", "bodies": ["pivot", "bar"], "lower": 1,
                                     "upper": -1})")) ==
          "joints.json: joints[1].upper: must not be below lower (1), got -1");
    CHECK(refusal(bar_scene(pin + R"({"type": "angle_limit", "bodies": ["pivot", "bar"]})")) ==
          "joints.json: joints[1]: an angle limit needs \"lower\", \"upper\" or both");
    CHECK(refusal(bar_scene(pin + R"({"type": "angle_limit", "bodies": ["pivot", "bar"], "upper": 4})")) ==
          "joints.json: joints[1].upper: must be in [-3.141592653589793, 3.141592653589793], got 4");
    CHECK(refusal(bar_scene(pin + R"({"type": "angle_limit", "bodies": ["pivot", "bar"],
                                     "lower": -3.141592653589793})"))
              .rfind("joints.json: joints[1] (\"pivot\", \"bar\"): angle limit: limit must lie in (−π, π]", 0) == 0);
    CHECK(refusal(bar_scene(pin + R"({"type": "angle_limit", "bodies": ["bar", "bar"], "upper": 1})")) ==
          "joints.json: joints[1] (\"bar\", \"bar\"): angle limit: needs two different bodies (or a body and the "
          "world), got body 1 twice");
    CHECK(refusal(bar_scene(R"({"type": "hinge", "bodies": ["pivot", "bar"]})")) ==
          "joints.json: joints[0].type: must be \"revolute\", \"distance\", \"angle_limit\" or \"incline\", got "
          "\"hinge\"");
  }
}
