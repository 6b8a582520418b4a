// Extreme but valid input (issue 9): mass ratios of 1000, a 1000 m/s projectile, Δt from 1e-4
// to 0.1, 0 and 200 sweeps, bodies spawned deeply overlapping, joints and circles, and scenes at
// the ends of every range a scene file allows (scene/scene_limits.h). Each scene is built by
// build_world and stepped by World::step, and after every step every body must be finite and
// exactly in the x–y plane; where physics gives an honest bound (penetration, speed, energy),
// that is checked too, with its reason. What cannot be simulated is refused before the first
// step, with one line naming it.
// Scenes lie in the x–y plane, y up; the ground is a static box whose top is y = 0.
#include <doctest/doctest.h>

#include <algorithm>
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
#include "scene/scene_json.h"
#include "scene/scene_limits.h"
#include "scene/scene_world.h"
#include "world_energy.h"

using namespace lamina;

namespace {

const double slop = ContactSettings().slop;  // penetration the contacts leave alone, in m
constexpr double g = 9.8;                    // |gravity| of the scenes below, in m/s²

// What is wrong with a body's state after a step, or "" when nothing is.
std::string fault_of(const RigidBody& b) {
  if (!b.has_finite_state()) return "state is not finite";
  // Planar scenes stay exactly planar: no tolerance, the 3D core must not leak.
  if (b.x.z() != 0.0 || b.v.z() != 0.0 || b.angular_velocity.x() != 0.0 ||
      b.angular_velocity.y() != 0.0 || b.q.x() != 0.0 || b.q.y() != 0.0) {
    return "left the x–y plane";
  }
  return "";
}

// A scene's World, every body inspected after every step; the first fault stops the run.
struct Watch {
  explicit Watch(const Scene& s, const WorldSettings& settings)
      : scene(s), world(build_world(s, settings)), start_energy(mechanical_energy(world)),
        peak_energy(start_energy) {}
  explicit Watch(const Scene& s) : Watch(s, world_settings(s)) {}

  // Steps for `seconds` of simulated time (whole steps); false at the first fault.
  bool run_for(double seconds) {
    const long steps = std::max(1L, std::lround(seconds / world.settings().dt));
    for (long k = 0; k < steps && fault.empty(); ++k) {
      world.step();
      ++steps_taken;
      inspect();
    }
    return fault.empty();
  }

  void inspect() {
    for (size_t i = 0; i < world.bodies().size(); ++i) {
      const RigidBody& b = world.bodies()[i];
      const std::string what = fault_of(b);
      if (!what.empty()) {
        fault = "step " + std::to_string(steps_taken) + ", body \"" + scene.bodies[i].name +
                "\": " + what;
        return;
      }
      if (b.is_static()) continue;
      top_speed = std::max(top_speed, b.v.norm());
    }
    peak_energy = std::max(peak_energy, mechanical_energy(world));
  }

  const RigidBody& body(const std::string& name) const {
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
      if (scene.bodies[i].name == name) return world.bodies()[i];
    }
    throw std::invalid_argument("no body " + name);
  }

  Scene scene;
  World world;
  long steps_taken = 0;
  std::string fault;         // the first fault, "" while there is none
  double start_energy;       // E at t = 0, in J
  double peak_energy;        // the largest E after any step, in J
  double top_speed = 0.0;    // the largest |v| of a moving body after any step, in m/s
};

// Runs a watched scene and requires every step sound, naming the first fault.
void require_sound(Watch& watch, double seconds) {
  const bool sound = watch.run_for(seconds);
  INFO(watch.fault);
  REQUIRE(sound);
}

BodyDescription box(const std::string& name, Vec2d position, Vec2d half_extents = {0.5, 0.5}) {
  BodyDescription b;
  b.name = name;
  b.position = position;
  b.shape.half_extents = half_extents;
  return b;
}

BodyDescription circle(const std::string& name, Vec2d position, double radius) {
  BodyDescription b;
  b.name = name;
  b.position = position;
  b.shape.type = ShapeType::circle;
  b.shape.radius = radius;
  return b;
}

// The ground, a static box 40 m × 1 m whose top is y = 0.
BodyDescription ground() {
  BodyDescription b = box("ground", {0.0, -0.5}, {20.0, 0.5});
  b.is_static = true;
  return b;
}

// The ground and `count` unit boxes placed touching, one on another: "box0" at the bottom.
Scene stack(int count, double dt = 1.0 / 60.0, int iterations = 10) {
  Scene s;
  s.dt = dt;
  s.iterations = iterations;
  s.bodies = {ground()};
  for (int i = 0; i < count; ++i) {
    s.bodies.push_back(box("box" + std::to_string(i), {0.0, 0.5 + i}));
  }
  return s;
}

// The energy of lifting every moving body by the slop, Σ m g slop, in J: what the split-impulse
// push-out may give bodies placed touching. Contacts with e = 0 and friction only take energy,
// and the semi-implicit step loses ½ m g² Δt² per step of free fall; the push-out is the one
// source, lifting a body out of a penetration without doing work on it.
double slop_energy(const World& world) { return lift_energy(world, slop); }

// Momentum along x of the bodies whose names start with `prefix`, in kg·m/s.
double momentum_x(const Watch& watch, const std::string& prefix) {
  double p = 0.0;
  for (size_t i = 0; i < watch.scene.bodies.size(); ++i) {
    if (watch.scene.bodies[i].name.rfind(prefix, 0) == 0) {
      p += watch.world.bodies()[i].mass * watch.world.bodies()[i].v.x();
    }
  }
  return p;
}

// A scene at the ends of scene_limits.h: under the strongest gravity (pulling sideways by
// `side` and down), a large box of density `heavy` thrown at the top speed and spin onto a
// small box of density `light`, and a ball pinned to the ground and thrown up, on a ground of the
// largest size placed at the largest coordinates.
Scene corner_scene(double dt, int iterations, double heavy, double light, double big, double side) {
  namespace limits = scene_limits;
  Scene s;
  s.dt = dt;
  s.iterations = iterations;
  s.gravity = {side * limits::gravity.high, limits::gravity.low};
  const double x = side * limits::coordinate.high;
  BodyDescription floor =
      box("floor", {x, limits::coordinate.low}, {limits::size.high, limits::size.high});
  floor.is_static = true;
  const double top = limits::coordinate.low + limits::size.high;  // the floor's top face, y
  BodyDescription small =
      box("small", {x, top + limits::size.low}, {limits::size.low, limits::size.low});
  small.density = light;
  BodyDescription large = box("large", {x, top + 2 * limits::size.low + big}, {big, big});
  large.density = heavy;
  large.velocity = {side * limits::speed.high, limits::speed.low};
  large.angular_velocity = side * limits::angular_speed.high;
  large.restitution = limits::restitution.high;
  large.friction = limits::friction.high;
  BodyDescription ball = circle("ball", {x - side * 3 * big, top + big}, big);
  ball.density = light;
  ball.velocity = {limits::speed.low, limits::speed.high};
  ball.angular_velocity = limits::angular_speed.low;
  s.bodies = {floor, small, large, ball};
  JointDescription pin;
  pin.bodies = {"floor", "ball"};
  pin.anchor = {ball.position[0], top};
  s.joints = {pin};
  return s;
}

// The reader's message for a scene written out as a file, or "(accepted)".
std::string refusal(const Scene& scene) {
  try {
    parse_scene(scene_to_json(scene), "edited.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(accepted)";
}

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

TEST_SUITE("NumericalGuards") {
  TEST_CASE("a mass ratio of 1000 either way stays finite and never gains energy") {
    // A box of density 1000 on a box of density 1, and the reverse, at every Δt of issue 9 and
    // with 10 and 200 sweeps. Energy bound: slop_energy (measured gain ≤ 6e-5 J, 0.1 % of it).
    for (double ratio : {1000.0, 1e-3}) {
      for (double dt : {1e-4, 1e-3, 1.0 / 60.0, 0.1}) {
        for (int iterations : {10, 200}) {
          CAPTURE(ratio);
          CAPTURE(dt);
          CAPTURE(iterations);
          Scene scene = stack(2, dt, iterations);
          scene.bodies[2].density = ratio;
          Watch watch(scene);
          require_sound(watch, 3.0);
          CHECK(watch.peak_energy <= watch.start_energy + slop_energy(watch.world));
        }
      }
    }
  }

  TEST_CASE("a light box rests on a heavy one at every Δt, a heavy one on a light one at Δt = 1e-4") {
    // Resting: penetration into the ground and between the boxes within the slop, which the
    // push-out leaves alone (measured ≤ 1.6e-4 m). With 10 sweeps PGS cannot carry a mass ratio
    // of 1000 at Δt = 1/60: the heavy box crushes the light one into the ground (finite, the
    // case above); at Δt = 1e-4 it holds (measured 2.2e-5 m).
    const auto deepest = [](double top_density, double dt) {
      Scene scene = stack(2, dt);
      scene.bodies[2].density = top_density;
      Watch watch(scene);
      double depth = 0.0;
      for (long k = 0; k < std::lround(3.0 / dt); ++k) {
        REQUIRE(watch.run_for(dt));
        const double bottom = watch.body("box0").x.y();
        depth = std::max({depth, 0.5 - bottom, 1.0 - (watch.body("box1").x.y() - bottom)});
      }
      return depth;
    };
    for (double dt : {1e-4, 1e-3, 1.0 / 60.0, 0.1}) {
      CAPTURE(dt);
      CHECK(deepest(1e-3, dt) <= slop);
    }
    CHECK(deepest(1000.0, 1e-4) <= slop);
  }

  TEST_CASE("a 1000 m/s projectile into a stack stays finite and never adds energy") {
    // A 0.2 m box or disc of density 1 at 1000 m/s into five unit boxes. Lamina has no continuous
    // collision detection: at Δt = 1e-3 and 1/60 the projectile moves 1 m and 17 m per step and
    // passes through (finite, documented); at Δt = 1e-4 (0.1 m per step) it hits, and the stack
    // takes up momentum, never more than the projectile brought (friction with the ground only
    // takes it away; measured 39 of 40 kg·m/s for the box, 29 of 31 for the disc).
    for (double dt : {1e-4, 1e-3, 1.0 / 60.0}) {
      for (bool disc : {false, true}) {
        CAPTURE(dt);
        CAPTURE(disc);
        Scene scene = stack(5, dt);
        BodyDescription projectile = disc ? circle("projectile", {-5.0, 2.5}, 0.1)
                                          : box("projectile", {-5.0, 2.5}, {0.1, 0.1});
        projectile.velocity = {1000.0, 0.0};
        scene.bodies.push_back(projectile);
        Watch watch(scene);
        const double brought = momentum_x(watch, "projectile");
        require_sound(watch, 3.0);
        CHECK(watch.peak_energy <= watch.start_energy + slop_energy(watch.world));
        if (dt == 1e-4) {
          CHECK(momentum_x(watch, "box") > 0.5 * brought);
          CHECK(momentum_x(watch, "box") <= brought);
        }
      }
    }
  }

  TEST_CASE("a box and a three-box stack are held from Δt = 1e-4 to 0.1") {
    // The box: penetration within the slop, and after 1 s slower than 1e-3 m/s (measured
    // 1.1e-14). The stack: its top box within 4 slops (2 cm) of where it was placed (measured
    // 1 cm at Δt = 0.1), and after 1 s each box slower than g Δt, the speed one step of free
    // fall gives: the contacts hold the boxes every step. Energy bound: slop_energy.
    for (double dt : {1e-4, 1e-3, 1.0 / 60.0, 0.1}) {
      for (int count : {1, 3}) {
        CAPTURE(dt);
        CAPTURE(count);
        Watch watch(stack(count, dt));
        const std::string top = "box" + std::to_string(count - 1);
        double depth = 0.0;
        double drop = 0.0;
        double late_speed = 0.0;
        for (long k = 0; k < std::lround(3.0 / dt); ++k) {
          REQUIRE(watch.run_for(dt));
          depth = std::max(depth, 0.5 - watch.body("box0").x.y());
          drop = std::max(drop, count - 0.5 - watch.body(top).x.y());
          if (k * dt < 1.0) continue;
          for (int i = 0; i < count; ++i) {
            late_speed = std::max(late_speed, watch.body("box" + std::to_string(i)).v.norm());
          }
        }
        CHECK(watch.peak_energy <= watch.start_energy + slop_energy(watch.world));
        if (count == 1) {
          CHECK(depth <= slop);
          CHECK(late_speed < 1e-3);
        } else {
          CHECK(drop <= 4 * slop);
          CHECK(late_speed < g * dt);
        }
      }
    }
  }

  TEST_CASE("with 0 sweeps every λ stays 0 and the bodies fall freely; 200 sweeps hold a stack") {
    // 0 sweeps leave λ at its warm start, 0 from the first step: the only force is gravity, so
    // each box's v is −g t, to rounding (the split-impulse push-out is added to v and taken back
    // each step: 1e-9 relative), and the stack falls through the ground. 200 sweeps hold it:
    // its top box within the slop of where it was placed, slower than 1e-3 m/s after 5 s.
    Watch falling(stack(5, 1.0 / 60.0, 0));
    for (int step = 1; step <= 120; ++step) {
      REQUIRE(falling.run_for(1.0 / 60.0));
      const Vec3 free_fall(0.0, -g * step / 60.0, 0.0);
      for (int i = 0; i < 5; ++i) {
        const Vec3& v = falling.body("box" + std::to_string(i)).v;
        REQUIRE((v - free_fall).norm() <= 1e-9 * free_fall.norm());
      }
    }
    CHECK(falling.body("box4").x.y() < 0.0);

    Watch held(stack(5, 1.0 / 60.0, 200));
    require_sound(held, 5.0);
    CHECK(std::abs(held.body("box4").x.y() - 4.5) <= slop);
    CHECK(held.body("box4").v.norm() < 1e-3);
  }

  TEST_CASE("boxes and discs spawned deeply overlapping separate without gaining speed") {
    // Split impulse moves positions only: v never keeps the push-out. Kept in v (Baumgarte),
    // two boxes at one place would leave at β d / (2 Δt) = 6 m/s each (measured 5.97), a pile
    // at up to 95 m/s, and a box half sunk into the ground would rise at β d / Δt = 6 m/s.
    // The push-out removes β of the penetration beyond the slop per step, so a depth d falls to
    // 1 mm beyond the slop within ln(d / 1 mm) / ln(1 / (1 − β)) ≈ 28 steps (d = 1 m; measured
    // 30): bound 60.
    SUBCASE("two boxes at one place") {
      Scene scene = stack(1);
      scene.bodies.push_back(box("twin", {0.0, 0.5}));
      Watch watch(scene);
      int apart_at = -1;
      for (int step = 1; step <= 180; ++step) {
        REQUIRE(watch.run_for(1.0 / 60.0));
        const Vec3 d = watch.body("twin").x - watch.body("box0").x;
        const double overlap = 1.0 - std::max(std::abs(d.x()), std::abs(d.y()));
        if (apart_at < 0 && overlap <= slop + 1e-3) apart_at = step;
      }
      CHECK(apart_at > 0);
      CHECK(apart_at <= 60);
      CHECK(watch.top_speed < 2.0);  // measured 0.12 m/s
    }
    SUBCASE("a box sunk into the ground to its centre, and to the ground's centre") {
      for (double y : {0.0, -0.5}) {
        CAPTURE(y);
        Scene scene = stack(1);
        scene.bodies[1].position = {0.0, y};
        Watch watch(scene);
        int out_at = -1;
        for (int step = 1; step <= 180; ++step) {
          REQUIRE(watch.run_for(1.0 / 60.0));
          if (out_at < 0 && watch.body("box0").x.y() >= 0.5 - slop - 1e-3) out_at = step;
        }
        CHECK(out_at > 0);
        CHECK(out_at <= 60);
        CHECK(watch.top_speed < 1e-3);  // held by the velocity solve from the first step: 8e-7 m/s
        // Lifted from y to 0.5 − slop: m g Δh is the energy the push-out adds
        const double lift = watch.body("box0").mass * g * (0.5 - y);
        CHECK(watch.peak_energy <= watch.start_energy + lift + slop_energy(watch.world));
      }
    }
    SUBCASE("a box sunk below the ground's centre leaves through its bottom") {
      // The nearest way out is down: it falls away under gravity alone, finite.
      Scene scene = stack(1);
      scene.bodies[1].position = {0.0, -0.9};
      Watch watch(scene);
      require_sound(watch, 3.0);
      CHECK(watch.body("box0").x.y() < -1.0);
      CHECK(watch.top_speed <= g * 3.0 * (1.0 + 1e-9));
    }
    SUBCASE("piles of ten discs and of eleven boxes at one place") {
      // Concentric discs push apart along +y and stand as a column; boxes spread sideways.
      for (bool discs : {true, false}) {
        CAPTURE(discs);
        Scene scene = stack(discs ? 0 : 1);
        for (int i = 0; i < 10; ++i) {
          const std::string name = "pile" + std::to_string(i);
          scene.bodies.push_back(discs ? circle(name, {0.0, 0.5}, 0.5) : box(name, {0.0, 0.5}));
        }
        Watch watch(scene);
        require_sound(watch, 5.0);
        CHECK(watch.top_speed < 2.0);  // measured 0.08 m/s (discs), 0.86 m/s (boxes)
      }
    }
  }

  TEST_CASE("joints stay finite at every Δt and sweep count, and gain no energy to speak of") {
    // The pendulum, see-saw, chain and bridge at Δt = 1e-4, 1/60, 0.1 with 0, 10 and 200 sweeps
    // (0: the joints hold nothing and everything falls). The pendulum's rod bias (eq. 3-14)
    // keeps its correction in v and gives back a little energy as it corrects the drift:
    // measured ≤ 0.95 % of m g L, bound 5 %. The see-saw and the chain stay within slop_energy
    // (measured ≤ 7e-4 J). The bridge's sagging pins give back up to 6 % of its start energy
    // (measured): no bound but finiteness.
    for (const std::string name : {"pendulum", "see-saw", "chain", "bridge"}) {
      for (double dt : {1e-4, 1.0 / 60.0, 0.1}) {
        for (int iterations : {0, 10, 200}) {
          CAPTURE(name);
          CAPTURE(dt);
          CAPTURE(iterations);
          Scene scene = builtin_scene(name);
          scene.dt = dt;
          scene.iterations = iterations;
          Watch watch(scene);
          require_sound(watch, dt < 1e-3 ? 1.0 : 3.0);  // 1 s: 10⁴ steps at Δt = 1e-4
          if (iterations == 0 || name == "bridge") continue;
          if (name == "pendulum") {
            const double swing = watch.body("bob").mass * g * 2.0;  // m g L, L = 2 m
            CHECK(watch.peak_energy <= watch.start_energy + 0.05 * swing);
          } else {
            CHECK(watch.peak_energy <= watch.start_energy + slop_energy(watch.world));
          }
        }
      }
    }
  }

  TEST_CASE("scenes at the ends of every scene limit stay finite") {
    // Every end of scene_limits.h at once (corner_scene): the densities' and sizes' ends give
    // mass ratios up to 6e22 between touching bodies, and the light bodies leave at up to
    // 1.7e11 m/s and 4e10 rad/s (measured over 20000 steps): meaningless, and finite. 2000 steps each (20 at
    // 10000 sweeps). Densities 1e200 times further out make every one non-finite in its first
    // step (measured).
    namespace limits = scene_limits;
    for (double dt : {limits::dt.low, 1.0 / 60.0, limits::dt.high}) {
      for (int iterations : {limits::iterations.low, 10, limits::iterations.high}) {
        for (double heavy : {limits::density.low, limits::density.high}) {
          for (double light : {limits::density.low, limits::density.high}) {
            for (double big : {limits::size.low, 1.0, limits::size.high / 2}) {
              for (double side : {-1.0, 1.0}) {
                CAPTURE(dt);
                CAPTURE(iterations);
                CAPTURE(heavy);
                CAPTURE(light);
                CAPTURE(big);
                CAPTURE(side);
                const Scene scene = corner_scene(dt, iterations, heavy, light, big, side);
                REQUIRE(refusal(scene) == "(accepted)");  // every value in range
                Watch watch(scene);
                require_sound(watch, (iterations == limits::iterations.high ? 20 : 2000) * dt);
              }
            }
          }
        }
      }
    }
  }

  TEST_CASE("a value just past either end of a scene limit is refused with its path and range") {
    // Each case edits one value of a valid scene (ground, box, disc, a revolute and a distance
    // joint) to the next double beyond an end of its range; the ends themselves are accepted.
    namespace limits = scene_limits;
    struct Limit {
      const char* path;
      limits::Range<double> range;
      std::function<void(Scene&, double)> edit;
    };
    const std::vector<Limit> cases = {
        {"dt", limits::dt, [](Scene& s, double v) { s.dt = v; }},
        {"beta", limits::beta, [](Scene& s, double v) { s.beta = v; }},
        {"gravity[0]", limits::gravity, [](Scene& s, double v) { s.gravity[0] = v; }},
        {"gravity[1]", limits::gravity, [](Scene& s, double v) { s.gravity[1] = v; }},
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
    JointDescription pin;
    pin.bodies = {"ground", "box0"};
    pin.anchor = {0.0, 1.0};
    JointDescription rod;
    rod.type = JointType::distance;
    rod.bodies = {"ground", "disc"};
    rod.anchors = {Vec2d{3.0, 3.0}, Vec2d{3.0, 0.5}};
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
    const Scene tied = post_tied_to_ground();
    CHECK_THROWS_WITH_AS(build_world(tied, world_settings(tied)),
                         "world: joint 1 joins only static bodies: it can move nothing",
                         std::invalid_argument);
    CHECK(refusal(tied) ==
          "edited.json: joints[1].bodies: a joint needs a body that moves, got the static bodies "
          "\"ground\" and \"pivot\"");
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
    CHECK(refusal(rod) == "edited.json: joints[0].anchors: the rod's two ends coincide, so it has "
                          "no length (a revolute joint pins two bodies)");
  }

  TEST_CASE("World settings and bodies out of range are refused; 0 sweeps are accepted") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (double dt : {0.0, -1e-3, nan, inf}) {
      CAPTURE(dt);
      WorldSettings settings;
      settings.dt = dt;
      CHECK_THROWS_AS(World{settings}, std::invalid_argument);
    }
    for (const Vec3& gravity : {Vec3(nan, -9.8, 0.0), Vec3(0.0, inf, 0.0), Vec3(0.0, -9.8, 1.0)}) {
      WorldSettings settings;
      settings.gravity = gravity;
      CHECK_THROWS_AS(World{settings}, std::invalid_argument);
    }
    WorldSettings settings;
    settings.iterations = -1;
    CHECK_THROWS_AS(World{settings}, std::invalid_argument);
    settings.iterations = 0;
    CHECK_NOTHROW(World{settings});

    World bodies;
    RigidBody body = box_body(1.0, 0.5, 0.5, Vec3(0.0, 1.0, 0.0));
    body.v.x() = nan;
    CHECK_THROWS_WITH_AS(bodies.add_body(body, Shape::box(0.5, 0.5)),
                         "world: body 0 has a position, orientation or velocity that is not finite",
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

  TEST_CASE("the longest step a scene file can ask for ends, finite") {
    // Δt = 1 s and 10000 sweeps over the 210-box pyramid: 0.16 s a step (Release, measured).
    Scene scene = pyramid_scene(20);
    scene.dt = scene_limits::dt.high;
    scene.iterations = scene_limits::iterations.high;
    Watch watch(scene);
    require_sound(watch, 2.0);
  }
}
