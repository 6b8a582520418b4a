// The methods a World steps with (contact/solvers.h): the text's own and Lamina's, what each
// switches, and the two behaviours that tell them apart on the text's own scene, the tilted
// landing of Fig 4-2..4-5 (the built-in box-on-ground-tilted: a 1 kg unit box dropped from
// y = 2 m, tilted 0.3 rad, μ = 0.6).
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/views/contact/contact_story.h"
#include "app/views/contact/world_explanation.h"
#include "contact/solvers.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

using namespace lamina;
using view::Fig4Moment;

namespace {

constexpr int landing_steps = 240;  // 4 s: the box lands at step 32 and rests by step 90

World landing(const std::string& solver) {
  Scene scene = builtin_scene("box-on-ground-tilted");
  scene.solver = solver;
  return build_world(scene, world_settings(scene));
}

// The moments of Fig 4-2..4-5 the landing goes through, each once however long it lasts.
std::vector<Fig4Moment> story(const std::string& solver) {
  World world = landing(solver);
  std::vector<Fig4Moment> moments;
  bool touched = false;
  WorldReport report;
  for (int k = 0; k < landing_steps; ++k) {
    world.step(report);
    const Fig4Moment moment = view::fig4_moment(report, 1, touched);
    touched = touched || moment != Fig4Moment::no_contact;
    if (moments.empty() || moments.back() != moment) moments.push_back(moment);
  }
  return moments;
}

// The last step's contacts of the landed box.
std::vector<ContactInfo> at_rest(const std::string& solver) {
  World world = landing(solver);
  for (int k = 0; k < landing_steps; ++k) world.step();
  return world.contacts();
}

}  // namespace

TEST_SUITE("Solvers") {
  TEST_CASE("the solvers are text and pgs; any other name is refused, naming them") {
    std::vector<std::string> names;
    for (const SolverInfo& s : solver_list()) names.push_back(s.name);
    CHECK(names == std::vector<std::string>{"text", "pgs"});
    CHECK(with_solver(WorldSettings(), "text").solver == "text");
    CHECK_THROWS_WITH_AS(with_solver(WorldSettings(), "block"),
                         "solver: no solver is named \"block\" (there are: text, pgs)",
                         std::invalid_argument);
  }

  TEST_CASE("text switches off every addition to the text; pgs keeps them all") {
    const WorldSettings text = with_solver(WorldSettings(), "text");
    CHECK(text.contact.correction == PositionCorrection::baumgarte);  // eq. 4-4, 4-5
    CHECK(text.contact.slop == 0.0);
    CHECK_FALSE(text.contact.restitution);
    CHECK_FALSE(text.contact.close_gaps);
    CHECK(text.contact.friction == FrictionRows::per_point);  // eq. 3-26, one per point
    CHECK_FALSE(text.cache.ties.break_ties);
    CHECK_FALSE(text.cache.reanchor);
    CHECK(text.cache.enabled);  // the text's cache (Fig 4-2..4-5) is the text's own
    const WorldSettings pgs = with_solver(text, "pgs");
    CHECK(pgs.contact.correction == PositionCorrection::split_impulse);
    CHECK(pgs.contact.slop == ContactSettings().slop);
    CHECK(pgs.contact.restitution);
    CHECK(pgs.contact.close_gaps);
    CHECK(pgs.contact.friction == FrictionRows::per_manifold);
    CHECK(pgs.cache.ties.break_ties);
    CHECK(pgs.cache.reanchor);
    // a World's defaults are pgs's
    CHECK(WorldSettings().solver == "pgs");
    CHECK(WorldSettings().contact.friction == FrictionRows::per_manifold);
  }

  TEST_CASE("with the text's method the landing tells Fig 4-2..4-5 in order, each once") {
    // From the run's own numbers (fig4_moment): the deepest corner alone (4-2), one corner
    // carrying the force while the box turns (4-3), both corners carrying it (4-4), then at rest
    // on both (4-5), and never back.
    const std::vector<Fig4Moment> expected{Fig4Moment::no_contact, Fig4Moment::first_contact,
                                           Fig4Moment::one_point, Fig4Moment::two_points,
                                           Fig4Moment::at_rest};
    CHECK(story("text") == expected);
    // Lamina's method tells the same story on this landing.
    CHECK(story("pgs") == expected);
  }

  TEST_CASE("pgs: a box at rest on two corners holds no friction against itself") {
    // One friction row per manifold (contact_rows.h): nothing pulls the corners towards each
    // other. Measured: |λ_t| < 1e-12 N at both corners after 4 s.
    const std::vector<ContactInfo> pgs = at_rest("pgs");
    REQUIRE(pgs.size() == 2);
    for (const ContactInfo& c : pgs) CHECK(std::abs(c.lambda_tangent) < 1e-9);  // N; m g = 9.8 N
  }

  TEST_CASE("text: the two corners' friction rows squeeze the resting box, equal and opposite") {
    // The text's two friction rows of a flat two-point manifold are the same row (their J differ
    // by ((r_a − r_b)·n) = 0 in ω_z), so only their sum is determined: PGS leaves the landing's
    // friction in them, pulling inwards, while their sum is the zero the box needs at rest.
    const std::vector<ContactInfo> text = at_rest("text");
    REQUIRE(text.size() == 2);
    const double a = text[0].lambda_tangent, b = text[1].lambda_tangent;
    CHECK(std::abs(a) > 1.0);  // N: measured 2.81 N, 96 % of μ λc = 0.6 × 4.9 N
    CHECK(std::abs(a + b) < 1e-6);  // N: equal and opposite, to PGS's convergence
  }

  TEST_CASE("--explain names a pgs friction row by both contacts it serves, a text one by its own") {
    // A box placed resting on the ground: one contact at step 0, both from step 1 (the cache
    // adds one deepest point a step). pgs writes one friction row
    // for the pair (row 2), text one per contact (rows 2 and 3); the titles come from the row map.
    for (const std::string solver : {"pgs", "text"}) {
      Scene scene = builtin_scene("box-on-ground-resting");
      scene.solver = solver;
      World world = build_world(scene, world_settings(scene));
      WorldReport report;
      world.step();
      world.step(report);
      std::vector<std::string> rows;
      for (const tutorial::Section& s : view::explain_world_step(world, report, {"ground", "box"})) {
        if (s.title.rfind("row ", 0) == 0) rows.push_back(s.title);
      }
      if (solver == "pgs") {
        REQUIRE(rows.size() == 3);
        CHECK(rows[2] == "row 2: friction row of contacts 0 and 1 (ground – box), one row at their "
                         "middle, along u1 = z × n");
      } else {
        REQUIRE(rows.size() == 4);
        CHECK(rows[2] == "row 2: friction row of contact 0 (ground – box), along u1 = z × n");
        CHECK(rows[3] == "row 3: friction row of contact 1 (ground – box), along u1 = z × n");
      }
    }
  }
  TEST_CASE("a step's explanation says which kept points were recycled: pgs's, never the text's") {
    // The resting box after 1 s: by pgs its pair is recycled (contact recycling, beyond the
    // text), both points kept without the narrow phase, and the explanation says so; by text
    // the narrow phase re-finds one corner each step and the other is kept as Fig 4-4 keeps it.
    for (const std::string solver : {"pgs", "text"}) {
      CAPTURE(solver);
      Scene scene = builtin_scene("box-on-ground-resting");
      scene.solver = solver;
      World world = build_world(scene, world_settings(scene));
      for (int k = 0; k < 60; ++k) world.step();
      WorldReport report;
      world.step(report);
      int recycled = 0, refound = 0, kept = 0;
      const tutorial::Explanation sections =
          view::explain_world_step(world, report, {"ground", "box"});
      for (const tutorial::Section& s : sections) {
        if (s.title.rfind("contact ", 0) != 0) continue;
        recycled += s.title.find("its pair recycled") != std::string::npos ? 1 : 0;
        refound += s.title.find("re-found") != std::string::npos ? 1 : 0;
        kept += s.title.find("kept by the cache, re-placed") != std::string::npos ? 1 : 0;
      }
      CHECK(recycled == (solver == "pgs" ? 2 : 0));
      CHECK(refound == (solver == "pgs" ? 0 : 1));
      CHECK(kept == (solver == "pgs" ? 0 : 1));
    }
  }
}
