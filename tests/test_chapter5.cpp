// The text's own stories, run: the contact cache of Fig 4-2..4-5 and the chapter-5 walk-through
// (eq. 5-1..5-21) at t = τ, τ + Δt, τ + 2Δt and t → ∞. Each test checks what the text says
// happens and writes its numbers as a Markdown table into the working directory
// (fig4_cache_story.md, ch5_walkthrough.md), from which docs/ch4-contact-model.md and
// docs/ch5-walkthrough.md take theirs. The text has z up; Lamina, like Box2D, has y up.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "contact/solvers.h"
#include "contact/world.h"
#include "markdown.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, in m/s²

// The box's corner a contact lies at: "−x" or "+x" of the box frame.
std::string corner(const RigidBody& box, const ContactInfo& c) {
  return (box.rotation.transpose() * (c.point - box.x)).x() < 0.0 ? "−x" : "+x";
}

// What step k solved, in one word per contact: corner, fresh or cached, pushing or not.
std::string signature(const RigidBody& box, const WorldReport& report) {
  std::string text;
  for (const ContactInfo& c : report.contacts()) {
    text += corner(box, c) + (c.cached ? "c" : "f") + (c.lambda_normal > 0.0 ? "+" : "0") + " ";
  }
  return text;
}

// One line of the Fig 4 story: step k, the box at t = k Δt, and each contact step k solved from
// it, as frame k of 04_contact_model's landing shows them.
std::string story_line(long step, const WorldReport& report) {
  const RigidBody& box = report.bodies[1];
  std::ostringstream line;
  line << "| " << step << " | " << fixed(planar_angle(box.q)) << " | "
       << fixed(box.angular_velocity.z()) << " |";
  for (const ContactInfo& c : report.contacts()) {
    line << " " << corner(box, c) << (c.cached ? " cached" : " fresh") << ", C " << fixed(c.separation)
         << ", λ " << fixed(c.lambda_normal) << " N;";
  }
  return line.str() + " |\n";
}

}  // namespace

TEST_SUITE("Chapter5") {
  TEST_CASE("Fig 4-2..4-5: one deepest point, then the cached a with the fresh b, then rest on two") {
    // The landing of 04_contact_model (the built-in box-on-ground-tilted: a 1 kg unit box
    // dropped from y = 2 m tilted by 0.3 rad, μ = 0.6) by the text's method, cache on then off.
    // The table lists a step when what it solved (corners, fresh or cached, pushing or not)
    // differs from the step before or after, so each run of alike steps shows its ends.
    std::ostringstream story;
    for (const bool cache : {true, false}) {
      WorldSettings settings = with_solver(WorldSettings(), "text");
      settings.cache.enabled = cache;
      World world(settings);
      world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, Material{0.6, 0.0});
      world.add_box(1.0, 0.5, 0.5, Vec3(0.0, 2.0, 0.0), 0.3, Material{0.6, 0.0});
      story << "\n#### Cache " << (cache ? "on" : "off") << "\n\n"
            << "| step | angle at t (rad) | ω at t (rad/s) | contacts solved: corner, fresh/cached, C (m), λ (N) |\n"
            << "|---|---|---|---|\n";
      long first_contact = -1;
      bool cached_a_with_fresh_b = false;
      int max_points = 0;
      constexpr long shown = 45;  // steps of the story from the first contact
      std::vector<std::string> lines, signatures;
      for (long step = 0; step < 600; ++step) {
        WorldReport report;
        world.step(report);
        const int points = static_cast<int>(report.contacts().size());
        max_points = std::max(max_points, points);
        if (points > 0 && first_contact < 0) {
          first_contact = step;
          // Fig 4-2, 4-3: the narrow phase finds one point, the deepest; it is pushed alone.
          CHECK(points == 1);
          CHECK_FALSE(report.contacts()[0].cached);
        }
        if (points == 2 && report.contacts()[0].cached != report.contacts()[1].cached) {
          // Fig 4-4: the cached a and the fresh b are solved together, at opposite corners.
          cached_a_with_fresh_b = true;
          CHECK(corner(report.bodies[1], report.contacts()[0]) != corner(report.bodies[1], report.contacts()[1]));
        }
        if (first_contact >= 0 && step < first_contact + shown) {
          lines.push_back(story_line(step, report));
          signatures.push_back(signature(report.bodies[1], report));
        }
      }
      bool elided = false;  // steps left out since the last line written
      for (std::size_t i = 0; i < lines.size(); ++i) {
        const bool shown_line = i == 0 || i + 1 == lines.size() ||
                                signatures[i] != signatures[i - 1] || signatures[i] != signatures[i + 1];
        if (!shown_line) {
          elided = true;
          continue;
        }
        if (elided) story << "| … | | | |\n";
        story << lines[i];
        elided = false;
      }
      REQUIRE(first_contact >= 0);
      CHECK(cached_a_with_fresh_b == cache);
      CHECK(max_points == (cache ? 2 : 1));
      story << "| … 599 | " << fixed(planar_angle(world.bodies()[1].q)) << " | "
            << fixed(world.bodies()[1].angular_velocity.z()) << " | " << world.contacts().size()
            << " point(s) at t = 10 s |\n";
    }
    std::ofstream("fig4_cache_story.md") << story.str();
  }

  TEST_CASE("the chapter-5 walk-through: a alone at τ, a cached with b at τ + Δt, f_c → m g") {
    // The text's scene, as 05_walkthrough runs it: box A (body 1 of the text, index 0 here) at
    // rest, V(τ) = 0, tilted so that corner a is 0.01 m into the fixed ground B (index 1). The
    // text's method (--solver text: Baumgarte bias, no slop) and no friction (chapter 5 has
    // none), so the rows are exactly eq. 5-8 and 5-19, in the text's order [box | ground].
    const auto walkthrough = [](double beta) {
      WorldSettings settings = with_solver(WorldSettings(), "text");
      settings.step.beta = beta;
      World world(settings);
      const Material frictionless{0.0, 0.0};
      const double tilt = 0.005;
      const double lowest = 0.5 * std::cos(tilt) + 0.5 * std::sin(tilt);  // corner a below x1
      world.add_box(1.0, 0.5, 0.5, Vec3(0.0, lowest - 0.01, 0.0), tilt, frictionless);
      world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, frictionless);
      return world;
    };
    World world = walkthrough(StepSettings().beta);
    const double dt = world.settings().step.dt;
    const double beta = world.settings().step.beta;
    const Vec3 N(0.0, 1.0, 0.0);  // the ground's normal, y up (the text's z)

    std::ostringstream out;
    const auto row = [&](const std::string& what, const std::string& eq, const std::string& value) {
      out << "| " << what << " | " << eq << " | " << value << " |\n";
    };
    const RigidBody& box = world.bodies()[0];
    Vec2 r_a_at_tau = Vec2::Zero();
    const char* titles[] = {"t = τ", "t = τ + Δt", "t = τ + 2Δt"};
    for (int k = 0; k < 3; ++k) {
      const RigidBody before = box;  // x1, R1, v1, ω1 at the start of the step
      WorldReport report;
      world.step(report);
      const StepReport& mlcp = report.velocity;
      const ContactPair& pair = world.contact_pairs().at(0);
      out << "\n#### " << titles[k] << "\n\n| quantity | eq. | value |\n|---|---|---|\n";
      if (k == 0) {
        row("M⁻¹: m1⁻¹ (kg⁻¹); I1⁻¹ (1/(kg·m²)); ground 0", "5-1",
            fixed(before.inverse_mass) + "; diag" + fixed_vector(Vec3(before.inverse_inertia_world.diagonal())));
        row("F_ext: f1 = m1 g (N)", "5-2", fixed_vector(Vec3(before.mass * world.settings().step.gravity)));
        row("V(τ) = [v1 ω1 v2 ω2]", "5-3", "0");
      }
      row("x1 (m); θ1 (rad)", "", fixed_vector(before.x) + "; " + fixed(planar_angle(before.q), 5));
      row("v1 (m/s); ω1 (rad/s)", k == 0 ? "5-3" : "3-5",
          fixed_vector(before.v) + "; " + fixed(before.angular_velocity.z()));
      for (int c = 0; c < pair.count; ++c) {
        const Contact& contact = pair.contacts[c];
        const bool second = c == 1;
        const char* name = second ? "b" : "a";
        const Vec2 r = contact.anchor[0];  // eq. 5-12: r = R1ᵀ (x − x1), box frame
        const Vec3 x_corner = before.x + before.rotation * lift(r);
        const Vec3 v_corner = before.v + before.angular_velocity.cross(x_corner - before.x);  // eq. 5-4
        const int j = contact.row;  // its row in the MLCP, as the step recorded it
        const std::string tag = std::string(name) + (contact.fresh() ? " (fresh)" : " (cached)");
        const std::array<double, 2> bounds = mlcp.mlcp.bounds(j, mlcp.solution.lambda.data());
        row("r_" + std::string(name) + " = R1ᵀ (x_" + name + " − x1) (m)", "5-12", fixed_vector(r));
        row("x_" + tag + " = x1 + R1 r (m)", "5-12", fixed_vector(x_corner));
        row("N·v_" + std::string(name) + ", v_" + name + " = v1 + ω1 × (x_" + name + " − x1) (m/s)",
            "5-4, 5-5", fixed(N.dot(v_corner)));
        row("ε = min(N·x − N·c, 0) = C (m)", k == 0 ? "5-6" : second ? "5-16" : "5-13",
            fixed(contact.separation, 5));
        row("ζ = −β ε (m); row ζ/Δt (m/s)", k == 0 ? "5-6" : second ? "5-16" : "5-13",
            fixed(-beta * std::min(contact.separation, 0.0), 5) + "; " + fixed(mlcp.mlcp.zeta(j), 5));
        row("J row, box block [Nᵀ ((p − x1) × N)ᵀ], p the contact point", k == 0 ? "5-8" : second ? "5-17" : "5-14",
            fixed_vector(mlcp.mlcp.jacobian(j, 0)));
        row("[λ⁻, λ⁺] (N)", k == 0 ? "5-10" : second ? "5-18" : "5-15",
            "[" + fixed(bounds[0]) + ", " + (std::isinf(bounds[1]) ? std::string("∞") : fixed(bounds[1])) + ")");
        row("η (m/s²); d = J B", "3-16", fixed(mlcp.mlcp.eta(j)) + "; " + fixed(mlcp.mlcp.d(j)));
        row("λ (N); impulse λ Δt (N·s)", k == 0 ? "5-9" : "5-21",
            fixed(mlcp.solution.lambda[j]) + "; " + fixed(mlcp.solution.lambda[j] * dt));
        // Eq. 5-10, 5-15, 5-18: a contact row only pushes.
        CHECK(bounds[0] == 0.0);
        CHECK(std::isinf(bounds[1]));
      }
      const Vec6 wrench = mlcp.constraint_wrench(0);
      row("f_c1 = Σ λ N (N); τ_c1 (N·m)", "5-9", fixed_vector(Vec3(wrench.head<3>())) + "; " + fixed(wrench[5]));
      if (k == 0) {
        // One row: the narrow phase gave the deepest corner a, nothing else (eq. 5-11).
        REQUIRE(pair.count == 1);
        CHECK(mlcp.mlcp.row_count() == 1);
        CHECK(pair.contacts[0].fresh());
        CHECK(pair.contacts[0].separation == doctest::Approx(-0.01).epsilon(1e-9));
        r_a_at_tau = pair.contacts[0].anchor[0];
        // At rest, one row: J V(τ+Δt) = (d λ − g) Δt must equal the asked velocity, so
        // λ = (asked/Δt + g) / d with d = m⁻¹ + I⁻¹ ((p − x1) × N)_z² (the lever from the
        // geometry: p lies 0.4975 m left of x1). Lamina asks ζ/Δt = β·0.01/Δt (eq. 4-5); eq. 5-7
        // read literally asks ζ = β·0.01 itself as the velocity, which is Lamina's step with β Δt
        // for β.
        const double lever = mlcp.mlcp.jacobian(0, 0)[5];
        CHECK(lever == doctest::Approx(-0.4975).epsilon(1e-3));  // −(x_a − x1)_x, the corner's x offset
        const double d = before.inverse_mass + before.inverse_inertia_world(2, 2) * lever * lever;
        const double g = -world.settings().step.gravity.y();
        const double lamina = (beta * 0.01 / dt / dt + g) / d;
        const double literal = (beta * 0.01 / dt + g) / d;
        CHECK(mlcp.solution.lambda[0] == doctest::Approx(lamina).epsilon(1e-9));
        World literal_world = walkthrough(beta * dt);
        WorldReport literal_report;
        literal_world.step(literal_report);
        CHECK(literal_report.velocity.solution.lambda[0] == doctest::Approx(literal).epsilon(1e-9));
        row("λ1 if eq. 5-7 is read literally, ζ1 = −β ε taken as m/s (N)", "5-7",
            fixed(literal_report.velocity.solution.lambda[0]));
      }
      if (k == 1) {
        // Two rows (eq. 5-19..5-21): a from the cache, re-placed from the same r_a, and b fresh.
        REQUIRE(pair.count == 2);
        CHECK(mlcp.mlcp.row_count() == 2);
        CHECK_FALSE(pair.contacts[0].fresh());
        CHECK(pair.contacts[0].anchor[0] == r_a_at_tau);
        CHECK(pair.contacts[1].fresh());
        CHECK(mlcp.solution.lambda[pair.contacts[0].row] > 0.0);
        CHECK(mlcp.solution.lambda[pair.contacts[1].row] > 0.0);
      }
    }
    for (int i = 3; i < 600; ++i) world.step();
    WorldReport last;
    world.step(last);
    const Vec6 wrench = last.velocity.constraint_wrench(0);
    out << "\n#### t → ∞ (after 10 s)\n\n| quantity | eq. | value |\n|---|---|---|\n";
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
