// Chapter 4 — the contact model. Five scenes, each frame showing the bodies at t with the
// contacts the step from t found and the λ it solved for them, and two beyond the text:
//   contact_geometry Fig 4-1: x1, r1, x2, r2 and n1 of the deepest point, a tilted box landing on
//                    a fixed box, with eq. 4-1's C computed from them (ch4/contact_geometry.cpp);
//   landing          Fig 4-2..4-5 told by the text's own method (--solver text, the default
//                    here): a unit box dropped tilted by 0.3 rad lands on one corner a, turns,
//                    corner b goes in while a is still cached, and it rests on both; the
//                    captions follow the forces each step solved (views/contact/contact_story.h)
//                    (--no-cache: the same drop without the cache, which never rests);
//   cache_on_vs_off  the same drop twice side by side, with and without the contact cache;
//   text_vs_pgs      the same drop by the text's method and by Lamina's (pgs), side by side, and
//                    the plot penetration.png (deepest corner below the ground against t);
//   friction_ramp    a box that sticks (tan θ < μ) and one that slides at g (sin θ − μ cos θ)
//                    (--no-cache: without the cache); in ch4/friction_ramp.cpp;
//   gjk, epa         beyond the text, the collision detection it leaves to [9] and [10]: GJK on
//                    a hexagon and a triangle apart and EPA on the same pair overlapping, one
//                    frame per iteration with the engine's numbers (ch4/gjk_scene.cpp,
//                    ch4/epa_scene.cpp; the pair drawn by ch4/pair_figure.cpp).
// The landing is the built-in scene box-on-ground-tilted (docs/ch4-contact-model.md), so
// `lamina run box-on-ground-tilted --solver text --explain K` and `04_contact_model --explain K`
// explain the same step.
#include <array>
#include <string>
#include <vector>

#include "app/harness/plot.h"
#include "app/harness/tutorial.h"
#include "ch4/contact_geometry.h"
#include "ch4/drop_run.h"
#include "ch4/friction_ramp.h"
#include "ch4/gjk_epa.h"
#include "contact/solvers.h"
#include "language/language.h"

namespace {

using namespace lamina;

const double dt = StepSettings().dt;  // Δt, in s (every scene's default)

tutorial::Explanation titled(const std::string& prefix, tutorial::Explanation e) {
  for (tutorial::Section& s : e) s.title = prefix + s.title;
  return e;
}

// Fig 4-2..4-5 as one full-width story.
class Landing : public tutorial::Scene {
 public:
  explicit Landing(const tutorial::Options& o) : run_(o.solver.value_or("text"), !o.no_cache) {}

  tutorial::SceneInfo info() const override {
    return {"landing", dt, 100, 1, {Vec2(-3.4, -1.7), Vec2(3.4, 2.8)}};
  }
  void step() override { run_.step(); }

  void draw(render::Frame& frame) const override {
    frame.caption = run_.moment();
    ch4::draw_ground(frame);
    run_.draw(frame, 0.0, colour());
    frame.panels.push_back(run_.panel(render::Corner::bottom_left, colour()));
    frame.legend_corner = render::Corner::bottom_right;
  }

  tutorial::Explanation explain() const override { return run_.explain(); }
  void record(tutorial::ViewerStep& step) const override { step = run_.viewer_step(); }

 private:
  render::Colour colour() const {
    return run_.cache() ? render::palette::blue : render::palette::vermillion;
  }
  ch4::DropRun run_;
};

// The same drop twice, side by side: two solvers, or the cache on and off.
struct Side {
  std::string solver;
  bool cache;
  render::Colour colour;
  std::string title;  // how the explanation names the run
};

class SideBySide : public tutorial::Scene {
 public:
  static constexpr double offset = 1.8;  // each drop's x distance from the frame's middle, in m

  SideBySide(std::string name, std::string caption, const Side& left, const Side& right)
      : name_(std::move(name)),
        caption_(std::move(caption)),
        sides_{left, right},
        runs_{ch4::DropRun(left.solver, left.cache), ch4::DropRun(right.solver, right.cache)} {}

  tutorial::SceneInfo info() const override {
    return {name_, dt, 100, 1, {Vec2(-5.4, -1.5), Vec2(5.4, 2.9)}};
  }
  void step() override {
    for (ch4::DropRun& run : runs_) run.step();
  }

  void draw(render::Frame& frame) const override {
    frame.caption = caption_;
    ch4::draw_ground(frame);
    const std::array<render::Corner, 2> corners{render::Corner::bottom_left,
                                                render::Corner::bottom_right};
    for (int k = 0; k < 2; ++k) {
      runs_[k].draw(frame, (2 * k - 1) * offset, sides_[k].colour);
      frame.panels.push_back(runs_[k].panel(corners[k], sides_[k].colour));
    }
    frame.paths.push_back({{Vec2(0.0, 0.0), Vec2(0.0, 2.9)}, render::palette::grid, false});
    frame.legend_corner = render::Corner::top_right;
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e = titled(sides_[0].title + " · ", runs_[0].explain());
    const tutorial::Explanation right = titled(sides_[1].title + " · ", runs_[1].explain());
    e.insert(e.end(), right.begin(), right.end());
    return e;
  }

 private:
  std::string name_, caption_;
  std::array<Side, 2> sides_;
  std::array<ch4::DropRun, 2> runs_;
};

// The text's method against Lamina's, and penetration.png over 4 s, whatever --frames rendered.
class TextVsPgs : public SideBySide {
 public:
  TextVsPgs()
      : SideBySide("text_vs_pgs",
                   tr("Fig 4-2..4-5 · one landing, two solvers: text, the text's method (left); pgs (right)"),
                   {"text", true, render::palette::blue, "text"},
                   {"pgs", true, render::palette::bluish_green, "pgs"}) {}

  void write_data(const std::filesystem::path& folder) const override {
    constexpr int steps = 240;
    // text with the cache is drawn last: until corner b lands it runs under text without.
    std::array<World, 3> worlds{ch4::drop_world("text", false), ch4::drop_world("pgs", true),
                                ch4::drop_world("text", true)};
    std::vector<std::vector<double>> rows;
    for (int s = 0; s <= steps; ++s) {
      if (s > 0) {
        for (World& w : worlds) w.step();
      }
      std::vector<double> row{s * dt};
      for (const World& w : worlds) row.push_back(1000.0 * ch4::penetration(w.bodies()[1]));
      row.push_back(1000.0 * worlds[1].settings().contact.slop);
      rows.push_back(row);
    }
    tutorial::write_plot(folder, {"penetration",
                                  tr("Tilted box landing: its deepest corner below the ground"),
                                  "t (s)",
                                  tr("penetration (mm)"),
                                  {{tr("text, cache off"), render::palette::vermillion, false},
                                   {tr("pgs, cache on"), render::palette::bluish_green, false},
                                   {tr("text, cache on"), render::palette::blue, false},
                                   {tr("pgs's slop (left uncorrected)"), render::palette::grey, true}},
                                  rows,
                                  "top right"});
  }
};

}  // namespace

int main(int argc, char** argv) {
  tutorial::TutorialInfo info{
      "04_contact_model",
      "ch4",
      "Chapter 4: the contact cache of Fig 4-2..4-5 (a tilted box landing by the text's method, "
      "cache on vs off, text vs pgs) and a friction ramp, with the penetration plot; beyond the "
      "text, GJK and EPA step by step on one pair of polygons",
      {render::Overlay::contacts, render::Overlay::normals, render::Overlay::forces,
       render::Overlay::centres}};
  info.has_cache = true;
  for (const SolverInfo& s : solver_list()) info.solvers.push_back(s.name);
  return tutorial::run_tutorial(
      argc, argv, info,
      {ch4::contact_geometry_scene(),
       [](const tutorial::Options& o) { return std::make_unique<Landing>(o); },
       [](const tutorial::Options&) {
         return std::make_unique<SideBySide>(
             "cache_on_vs_off",
             tr("Fig 4-2..4-5 · the same landing with the contact cache (left) and without"),
             Side{"text", true, render::palette::blue, tr("cache on")},
             Side{"text", false, render::palette::vermillion, tr("cache off")});
       },
       tutorial::scene<TextVsPgs>(), ch4::friction_ramp_scene(), ch4::gjk_scene(),
       ch4::epa_scene()});
}
