// The pitfalls (motion/pitfalls.h): each classic mistake, put back by its switch, does what the
// mistake does — shown against an analytic number or against the same run without it — and
// nothing when off. (lambda-b1 is checked in test_pgs_solver.cpp, beside TransposeMultiply.)
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/world.h"
#include "motion/integrator.h"
#include "motion/pitfalls.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

using namespace lamina;

namespace {

Pitfalls only(Pitfall p) {
  Pitfalls set;
  set.add(p);
  return set;
}

World scene_world(const std::string& name, const std::string& method, Pitfalls pitfalls) {
  Scene scene = builtin_scene(name);
  scene.solver = method;
  scene.step.pitfalls = pitfalls;
  return build_world(scene, world_settings(scene));
}

}  // namespace

TEST_SUITE("Pitfalls") {
  TEST_CASE("the pitfalls by name; any other name is refused, naming them") {
    std::vector<std::string> names;
    for (const PitfallInfo& p : pitfall_list()) {
      names.push_back(p.name);
      CHECK(pitfall_named(p.name) == p.pitfall);
      CHECK(pitfall_name(p.pitfall) == p.name);
    }
    CHECK(names == std::vector<std::string>{"lambda-b1", "no-renormalisation", "clamp-increment",
                                            "no-warm-start", "crude-friction", "baumgarte-no-slop"});
    CHECK_THROWS_WITH_AS(pitfall_named("typo"),
                         "pitfall: none is named \"typo\" (there are: lambda-b1, no-renormalisation, "
                         "clamp-increment, no-warm-start, crude-friction, baumgarte-no-slop)",
                         std::invalid_argument);
    CHECK(Pitfalls().empty());
    CHECK(StepSettings().pitfalls.empty());
  }

  TEST_CASE("no-renormalisation: |q| grows by √(1 + (ω Δt / 2)²) a step, as eq. 2-6's sum does") {
    // A box spinning about z at ω = 20 rad/s, no forces: q + ½ ω̂ q Δt with ω̂ q ⟂ q for a planar
    // q gives |q_{k+1}|² = |q_k|² (1 + (ω Δt/2)²), exactly but for rounding (1e-12 relative
    // over 60 steps); renormalised, |q| = 1 to 1e-15.
    const double omega = 20.0, dt = 1.0 / 60.0;
    for (const bool pitfall : {false, true}) {
      CAPTURE(pitfall);
      RigidBody box = box_body(1.0, 0.5, 0.5, Vec3::Zero(), 0.0);
      box.angular_velocity = Vec3(0.0, 0.0, omega);
      for (int k = 0; k < 60; ++k) {
        integrate(box, dt, Integration::semi_implicit,
                  pitfall ? only(Pitfall::no_renormalisation) : Pitfalls());
      }
      const double expected = pitfall ? std::pow(1.0 + std::pow(omega * dt / 2.0, 2), 30.0) : 1.0;
      CHECK(std::abs(box.q.norm() - expected) <= 1e-12 * expected);
    }
  }

  TEST_CASE("clamp-increment: a contact's λ can only grow within a step, never fall back") {
    // Clamping the increment Δ to [0, ∞) instead of λ + Δ: a contact row's λ never decreases
    // within a solve, so it ends at or above its warm start λ_exp whatever the step asks — a
    // contact pushing harder than it should (the 5-box stack of chapter 6 blows apart). The
    // tilted landing by pgs: with the pitfall no contact row ends below its λ_exp in 120 steps;
    // without it, λ falls below λ_exp somewhere (the load moving from corner to corner).
    for (const bool pitfall : {false, true}) {
      CAPTURE(pitfall);
      World world = scene_world("box-on-ground-tilted", "pgs",
                                pitfall ? only(Pitfall::clamp_increment) : Pitfalls());
      int fell = 0;  // contact rows that ended more than 1e-9 N below their warm start
      for (int k = 0; k < 120; ++k) {
        WorldReport report;
        world.step(report);
        const Mlcp& mlcp = report.velocity.mlcp;
        const Eigen::VectorXd& lambda = report.velocity.solution.lambda;
        for (int i = 0; i < lambda.size(); ++i) {
          const auto [lo, hi] = mlcp.bounds(i, lambda.data());
          const bool contact = mlcp.friction_of(i) < 0 && lo == 0.0 && std::isinf(hi);
          if (contact && lambda[i] < report.velocity.lambda_exp[i] - 1e-9) ++fell;
        }
      }
      MESSAGE("clamp-increment " << pitfall << ": contact rows that fell below λ_exp: " << fell);
      if (pitfall) {
        CHECK(fell == 0);
      } else {
        CHECK(fell > 10);
      }
    }
  }

  TEST_CASE("no-warm-start: every step starts from λ = 0; with the cache it starts from its λ") {
    for (const bool pitfall : {false, true}) {
      CAPTURE(pitfall);
      World world = scene_world("box-on-ground-resting", "pgs",
                                pitfall ? only(Pitfall::no_warm_start) : Pitfalls());
      for (int k = 0; k < 30; ++k) world.step();
      WorldReport report;
      world.step(report);
      const double largest = report.velocity.lambda_exp.cwiseAbs().maxCoeff();
      if (pitfall) {
        CHECK(largest == 0.0);
      } else {
        CHECK(largest > 0.4 * 9.8);  // the cached λ: about m g / 2 per corner, 1 kg
      }
    }
  }

  TEST_CASE("crude-friction: ±μ m g per point holds a box that ±μ λc lets slide") {
    // friction-ramp: a 1 kg box on a 30° ramp, μ = 0.4 < tan 30° = 0.577: by Coulomb it slides
    // at g (sin 30° − 0.4 cos 30°) = 1.505 m/s². The crude bound gives its two-point manifold's
    // friction row ±2 μ m g = ±7.84 N, more than m g sin 30° = 4.9 N: it sticks.
    for (const bool pitfall : {false, true}) {
      CAPTURE(pitfall);
      World world = scene_world("friction-ramp", "pgs",
                                pitfall ? only(Pitfall::crude_friction) : Pitfalls());
      for (int k = 0; k < 30; ++k) world.step();
      const Vec3 before = world.bodies()[1].x;
      WorldReport report;
      world.step(report);
      for (int k = 0; k < 59; ++k) world.step();
      const double moved = (world.bodies()[1].x - before).norm();  // over 1 s
      if (pitfall) {
        CHECK(moved < 1e-3);
        // the friction row's bounds: fixed, ±2 μ m g
        const Mlcp& mlcp = report.velocity.mlcp;
        const int friction_row = mlcp.row_count() - 1;
        const std::array<double, 2> bounds = mlcp.bounds(friction_row, report.velocity.solution.lambda.data());
        CHECK(mlcp.friction_of(friction_row) == -1);
        CHECK(bounds[1] == doctest::Approx(2 * 0.4 * world.bodies()[1].mass * 9.8).epsilon(1e-12));
      } else {
        CHECK(moved > 0.5);  // ½ a t² ≈ 0.75 m, after sliding from rest
      }
    }
  }

  TEST_CASE("baumgarte-no-slop: the World takes Baumgarte's bias with no slop, whatever the method") {
    for (const std::string method : {"pgs", "islands"}) {
      CAPTURE(method);
      const World plain = scene_world("box-on-ground", method, Pitfalls());
      const World slipped = scene_world("box-on-ground", method, only(Pitfall::baumgarte_no_slop));
      CHECK(plain.settings().contact.correction == PositionCorrection::split_impulse);
      CHECK(plain.settings().contact.slop == 0.005);
      CHECK(slipped.settings().contact.correction == PositionCorrection::baumgarte);
      CHECK(slipped.settings().contact.slop == 0.0);
    }
  }
}
