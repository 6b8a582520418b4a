// The text's own stories, run: the contact cache of Fig 4-2..4-5 and the chapter-5 walk-through
// (eq. 5-1..5-21) at t = τ, τ + Δt, τ + 2Δt and t → ∞. Each test checks what the text says
// happens and writes its numbers as a Markdown table into the working directory
// (fig4_cache_story.md, ch5_walkthrough.md), from which docs/ch4-contact-model.md and
// docs/ch5-walkthrough.md take theirs. The text has z up; Lamina, like Box2D, has y up.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "contact/world.h"
#include "markdown.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, in m/s²

// The box's corner a contact lies at: "−x" or "+x" of the box frame.
std::string corner(const RigidBody& box, const ContactInfo& c) {
  return (box.rotation.transpose() * (c.point - box.x)).x() < 0.0 ? "−x" : "+x";
}

// One line of the Fig 4 story: the step, the pose after it, and each contact solved in it.
std::string story_line(int step, const World& world, const WorldReport& report) {
  const RigidBody& box = world.bodies()[1];
  std::ostringstream line;
  line << "| " << step << " | " << fixed(planar_angle(box.q)) << " | "
       << fixed(box.angular_velocity.z()) << " |";
  for (const ContactInfo& c : report.contacts()) {
    line << " " << corner(box, c) << (c.cached ? " cached" : " fresh") << ", C " << fixed(c.separation)
         << ", λΔt " << fixed(c.lambda_normal * world.settings().step.dt) << ";";
  }
  return line.str() + " |\n";
}

}  // namespace

TEST_SUITE("Chapter5") {
  TEST_CASE("Fig 4-2..4-5: one deepest point, then the cached a with the fresh b, then rest on two") {
    // The comparison scene's tilted drop (test_box2d_comparison.cpp), cache on then off.
    std::ostringstream story;
    for (const bool cache : {true, false}) {
      WorldSettings settings;
      settings.cache.enabled = cache;
      World world(settings);
      world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, Material{0.6, 0.0});
      world.add_box(1.0, 0.5, 0.5, Vec3(0.0, 2.0, 0.0), 0.3, Material{0.6, 0.0});
      story << "\n### Cache " << (cache ? "on" : "off") << "\n\n"
            << "| step | angle (rad) | ω (rad/s) | contacts solved: corner, fresh/cached, C (m), λΔt (N·s) |\n"
            << "|---|---|---|---|\n";
      int first_contact = 0;
      bool cached_a_with_fresh_b = false;
      int max_points = 0;
      for (int step = 1; step <= 600; ++step) {
        WorldReport report;
        world.step(report);
        const int points = static_cast<int>(report.contacts().size());
        max_points = std::max(max_points, points);
        if (points > 0 && first_contact == 0) {
          first_contact = step;
          // Fig 4-2, 4-3: the narrow phase finds one point, the deepest; it is pushed alone.
          CHECK(points == 1);
          CHECK_FALSE(report.contacts()[0].cached);
        }
        if (points == 2 && report.contacts()[0].cached != report.contacts()[1].cached) {
          // Fig 4-4: the cached a and the fresh b are solved together, at opposite corners.
          cached_a_with_fresh_b = true;
          CHECK(corner(world.bodies()[1], report.contacts()[0]) != corner(world.bodies()[1], report.contacts()[1]));
        }
        if (first_contact > 0 && step < first_contact + (cache ? 25 : 12)) {
          story << story_line(step, world, report);
        }
      }
      REQUIRE(first_contact > 0);
      CHECK(cached_a_with_fresh_b == cache);
      CHECK(max_points == (cache ? 2 : 1));
      story << "| … 600 | " << fixed(planar_angle(world.bodies()[1].q)) << " | "
            << fixed(world.bodies()[1].angular_velocity.z()) << " | " << world.contacts().size()
            << " point(s) |\n";
    }
    std::ofstream("fig4_cache_story.md") << story.str();
  }

  TEST_CASE("the chapter-5 walk-through: a alone at τ, a cached with b at τ + Δt, f_c → m g") {
    // The text's scene: box A (body 2 here; the ground is body 1) at rest, V(τ) = 0, tilted so
    // that corner a is 0.01 m into the ground. The text's method: Baumgarte bias, no slop, and
    // no friction (chapter 5 has none), so the rows are exactly eq. 5-8 and 5-19.
    WorldSettings settings;
    settings.contact.correction = PositionCorrection::baumgarte;
    settings.contact.slop = 0.0;
    World world(settings);
    const Material frictionless{0.0, 0.0};
    world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, frictionless);
    const double tilt = 0.005;
    const double lowest = 0.5 * std::cos(tilt) + 0.5 * std::sin(tilt);  // corner a below the centre
    world.add_box(1.0, 0.5, 0.5, Vec3(0.0, lowest - 0.01, 0.0), tilt, frictionless);
    const double dt = settings.step.dt;
    const double beta = settings.step.beta;

    std::ostringstream out;
    const auto row = [&](const std::string& what, const std::string& eq, const std::string& value) {
      out << "| " << what << " | " << eq << " | " << value << " |\n";
    };
    const RigidBody& box = world.bodies()[1];
    Vec2 r_a_at_tau = Vec2::Zero();
    const char* titles[] = {"t = τ", "t = τ + Δt", "t = τ + 2Δt"};
    for (int k = 0; k < 3; ++k) {
      const RigidBody before = box;  // x1, R1, v1, ω1 at the start of the step
      WorldReport report;
      world.step(report);
      const StepReport& mlcp = report.velocity;
      const ContactPair& pair = world.contact_pairs().at(0);
      out << "\n### " << titles[k] << "\n\n| quantity | eq. | value |\n|---|---|---|\n";
      if (k == 0) {
        row("M⁻¹: m1⁻¹ (kg⁻¹); I1⁻¹ (1/(kg·m²)); ground 0", "5-1",
            fixed(before.inverse_mass) + "; diag" + fixed_vector(Vec3(before.inverse_inertia_world.diagonal())));
        row("F_ext: f1 = m1 g (N)", "5-2", fixed_vector(Vec3(before.mass * settings.step.gravity)));
        row("V(τ) = [v1 ω1 v2 ω2]", "5-3", "0");
      }
      row("x1 (m); θ1 (rad)", "", fixed_vector(before.x) + "; " + fixed(planar_angle(before.q), 5));
      row("v1 (m/s); ω1 (rad/s)", "", fixed_vector(before.v) + "; " + fixed(before.angular_velocity.z()));
      for (int c = 0; c < pair.count; ++c) {
        const Contact& contact = pair.contacts[c];
        const char* name = c == 0 ? "a" : "b";
        const Vec2 r = contact.anchor[1];  // eq. 5-12: r = R1ᵀ (x − x1), box frame
        const Vec3 x_corner = before.x + before.rotation * lift(r);
        const int j = contact.row;  // its row in the MLCP, as the step recorded it
        const std::string tag = std::string(name) + (contact.fresh ? " (fresh)" : " (cached)");
        row("r_" + std::string(name) + " = R1ᵀ (x_" + name + " − x1) (m)", "5-12", fixed_vector(r));
        row("x_" + tag + " = x1 + R1 r (m)", "5-12", fixed_vector(x_corner));
        row("ε = min(N·x − N·c, 0) = C (m)", k == 0 ? "5-6" : "5-13, 5-16", fixed(contact.separation, 5));
        row("ζ = −β ε (m); row ζ/Δt (m/s)", k == 0 ? "5-6" : "5-13, 5-16",
            fixed(-beta * std::min(contact.separation, 0.0), 5) + "; " + fixed(mlcp.mlcp.zeta(j), 5));
        row("J row, box block [Nᵀ ((p − x1) × N)ᵀ], p the contact point", k == 0 ? "5-8" : "5-14, 5-17, 5-19",
            fixed_vector(mlcp.mlcp.jacobian(j, 0)));
        row("η (m/s²); d = J B", "3-16", fixed(mlcp.mlcp.eta(j)) + "; " + fixed(mlcp.mlcp.d(j)));
        row("λ (N); impulse λ Δt (N·s)", k == 0 ? "5-9..5-11" : "5-21",
            fixed(mlcp.solution.lambda[j]) + "; " + fixed(mlcp.solution.lambda[j] * dt));
      }
      const Vec6 wrench = mlcp.constraint_wrench(1);
      row("f_c1 = Σ λ N (N); τ_c1 (N·m)", "5-9", fixed_vector(Vec3(wrench.head<3>())) + "; " + fixed(wrench[5]));
      if (k == 0) {
        // One row: the narrow phase gave the deepest corner a, nothing else (eq. 5-11).
        REQUIRE(pair.count == 1);
        CHECK(mlcp.mlcp.row_count() == 1);
        CHECK(pair.contacts[0].fresh);
        CHECK(pair.contacts[0].separation == doctest::Approx(-0.01).epsilon(1e-9));
        r_a_at_tau = pair.contacts[0].anchor[1];
      }
      if (k == 1) {
        // Two rows (eq. 5-19..5-21): a from the cache, re-placed from the same r_a, and b fresh.
        REQUIRE(pair.count == 2);
        CHECK(mlcp.mlcp.row_count() == 2);
        CHECK_FALSE(pair.contacts[0].fresh);
        CHECK(pair.contacts[0].anchor[1] == r_a_at_tau);
        CHECK(pair.contacts[1].fresh);
        CHECK(mlcp.solution.lambda[pair.contacts[0].row] > 0.0);
        CHECK(mlcp.solution.lambda[pair.contacts[1].row] > 0.0);
      }
    }
    for (int i = 3; i < 600; ++i) world.step();
    WorldReport last;
    world.step(last);
    const Vec6 wrench = last.velocity.constraint_wrench(1);
    out << "\n### t → ∞ (after 10 s)\n\n| quantity | eq. | value |\n|---|---|---|\n";
    row("f_c1 (N), against m1 g = " + fixed(box.mass * g) + " N", "t → ∞", fixed_vector(Vec3(wrench.head<3>()), 6));
    row("τ_c1 (N·m)", "t → ∞", fixed(wrench[5], 6));
    const ContactPair& resting = last.pairs.at(0);
    REQUIRE(resting.count == 2);  // at rest on both corners
    const auto lambda_of = [&](int k) { return last.velocity.solution.lambda[resting.contacts[k].row]; };
    row("λ1, λ2 (N)", "", fixed(lambda_of(0), 6) + ", " + fixed(lambda_of(1), 6));
    // The text: f_c1 → m1 (0, 9.8) and τ_c1 → 0 (PGS warm started at rest; measured 1e-9).
    CHECK(wrench[1] == doctest::Approx(box.mass * g).epsilon(1e-6));
    CHECK(std::abs(wrench[5]) < 1e-6);
    std::ofstream("ch5_walkthrough.md") << out.str();
  }
}
