// Chapter 4 — the contact model. Three scenes, each frame showing the bodies at t with the
// contacts the step from t found and the λ it solved for them:
//   landing          Fig 4-2..4-5: a unit box dropped tilted by 0.3 rad lands on one corner a,
//                    turns, corner b goes in while a is still cached, and it rests on both
//                    (--no-cache: the same drop without the cache, which never rests);
//   cache_on_vs_off  the same drop twice side by side, with and without the contact cache, and
//                    the plot penetration.png (deepest corner below the ground against t);
//   friction_ramp    a box that sticks (tan θ < μ) and one that slides at g (sin θ − μ cos θ)
//                    (--no-cache: without the cache); in ch4/friction_ramp.cpp.
// The landing is the built-in scene box-on-ground-tilted (docs/ch4-contact-model.md): ground half
// extents (20, 0.5), top at y = 0, so `lamina run box-on-ground-tilted --explain K` and
// `04_contact_model --explain K` explain the same step.
#include <algorithm>
#include <array>
#include <cmath>

#include "app/harness/format.h"
#include "app/harness/plot.h"
#include "app/harness/tutorial.h"
#include "ch4/friction_ramp.h"
#include "app/views/contact/stepped_world.h"
#include "app/views/contact/world_explanation.h"
#include "app/views/contact/world_view.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace {

using namespace lamina;
using tutorial::fixed;

const double dt = StepSettings().dt;             // Δt, in s (every scene's default)
const double g = -StepSettings().gravity.y();    // |g|, in m/s²
constexpr double force_scale = 0.1;     // arrow length per λ, in m per N
constexpr double longest_force = 16.0;  // forces above this (landing impacts) are drawn cut, in N
constexpr double at_rest = 1e-2;        // |v| (m/s) and |ω| (rad/s) below this count as resting

// The docs' scene, the built-in box-on-ground-tilted: the ground (body 0), then the unit box of
// 1 kg dropped from y = 2 m tilted by 0.3 rad (body 1), μ = 0.6, e = 0 (the Box2D comparison's).
const Scene& drop_scene() {
  static const Scene scene = builtin_scene("box-on-ground-tilted");
  return scene;
}

const std::vector<std::string> drop_names{"ground", "box"};

World drop_world(bool cache) {
  WorldSettings settings = world_settings(drop_scene());
  settings.cache.enabled = cache;
  return build_world(drop_scene(), settings);
}

// How deep the box's lowest corner is below the ground's top y = 0, in m (0 when above).
double penetration(const RigidBody& box) {
  const double angle = planar_angle(box.q);
  const double reach = 0.5 * std::abs(std::sin(angle)) + 0.5 * std::abs(std::cos(angle));
  return std::max(0.0, reach - box.x.y());
}

// Landing impacts are tens of times the weight: an arrow longer than `longest_force` is drawn
// at that length, and a label `offset` from its tip gives the force.
void cut_arrow(render::Frame& frame, const Vec2& from, const Vec2& direction, double& force,
               const std::string& symbol, render::Colour colour, const Vec2& offset) {
  if (std::abs(force) <= longest_force) return;
  const Vec2 tip = from + force_scale * std::copysign(longest_force, force) * direction;
  frame.labels.push_back({tip + offset, symbol + " = " + fixed(force, 0) + " N (arrow cut)",
                          colour, render::Label::Align::left});
  force = std::copysign(longest_force, force);
}

// Roughly where a contact's corner is: the point lies midway between the corner and the ground's
// surface, so the corner is near c + (C/2) n (exactly for a fresh point).
Vec3 contact_corner(const ContactInfo& c) { return c.point + 0.5 * c.separation * c.normal; }

// One run of the tilted drop and what the story has seen so far. It shows step k: the state at
// t = k Δt with what step k solved from it.
class DropRun {
 public:
  explicit DropRun(bool cache) : cache_(cache), run_(drop_world(cache)) { step(); }

  void step() {
    run_.step();
    observe();
  }

  tutorial::Explanation explain() const {
    return view::explain_world_step(run_.world(), run_.report(), drop_names);
  }
  bool cache() const { return cache_; }

  // Draws the ground-less part of the run (box, contacts, corner names), shifted by `dx` in x.
  void draw(render::Frame& frame, double dx, render::Colour colour) const {
    const Vec2 shift(dx, 0.0);
    render::Body box = view::body_view(box_at_t(), run_.world().shape(1), tint(colour, 0.35));
    box.centre += shift;
    frame.bodies.push_back(box);
    for (const ContactInfo& c : run_.report().contacts()) {
      render::Contact view = view::contact_view(c);
      view.point += shift;
      cut_arrow(frame, view.point, view.normal, view.normal_force, "λ_n",
                render::palette::bluish_green, Vec2(0.08, 0.0));
      cut_arrow(frame, view.point, view.tangent, view.friction_force, "λ_t",
                render::palette::orange, Vec2(0.0, -0.2));
      frame.contacts.push_back(view);
      const bool left = corner_side(c) < 0.0;
      frame.labels.push_back({view.point + Vec2(left ? -0.14 : 0.14, 0.1), corner_name(c),
                              render::palette::ink,
                              left ? render::Label::Align::right : render::Label::Align::left});
    }
  }

  // The run's numbers: pose, spin, and each contact with its C and λ.
  render::Panel panel(render::Corner corner, render::Colour colour) const {
    const RigidBody& box = box_at_t();
    render::Panel p;
    p.corner = corner;
    p.title = cache_ ? "cache on" : "cache off";
    p.title_colour = colour;
    p.lines = {"θ = " + fixed(planar_angle(box.q), 3) + " rad   ω = " +
                   fixed(box.angular_velocity.z(), 2) + " rad/s",
               "penetration = " + fixed(1000.0 * penetration(box), 1) + " mm"};
    double total = 0.0, friction = 0.0;
    for (const ContactInfo& c : run_.report().contacts()) {
      p.lines.push_back(corner_name(c) + (c.cached ? " cached" : " fresh ") +
                        "  C = " + fixed(c.separation, 4) + " m  λ_n = " +
                        fixed(c.lambda_normal, 1) + " N  λ_t = " + fixed(c.lambda_tangent, 1) +
                        " N");
      total += c.lambda_normal;
      friction += c.lambda_tangent;
    }
    if (run_.report().contacts().empty()) p.lines.push_back("no contact: falling under m g");
    p.lines.push_back("Σ λ_n = " + fixed(total, 2) + " N (m g = " + fixed(g, 2) + " N), Σ λ_t = " +
                      fixed(friction, 2) + " N");
    return p;
  }

  // The moment of the story the run is at, in the figures' words.
  std::string moment() const {
    const std::vector<ContactInfo> contacts = run_.report().contacts();
    const RigidBody& box = box_at_t();
    if (contacts.empty()) {
      return frames_in_contact_ == 0 ? "falling: no contact yet" : "in the air: no contact";
    }
    if (frames_in_contact_ == 1) {
      return "Fig 4-2 · first contact: collision detection gives one point, the deepest corner a";
    }
    if (contacts.size() == 1) {
      return cache_ ? "Fig 4-3 · the engine pushes at its one point; the box turns over it"
                    : "cache off · only this step's deepest point: the box see-saws, never rests";
    }
    if (box.v.norm() < at_rest && std::abs(box.angular_velocity.z()) < at_rest) {
      return "Fig 4-5 · at rest on two points, each carrying m g / 2 = 4.9 N";
    }
    for (const ContactInfo& fresh : contacts) {
      for (const ContactInfo& cached : contacts) {
        if (!fresh.cached && cached.cached) {
          return "Fig 4-4 · corner " + corner_name(fresh) + " goes in while " +
                 corner_name(cached) + " is still cached: both solved together";
        }
      }
    }
    return "Fig 4-4 · two points solved together";
  }

 private:
  const RigidBody& box_at_t() const { return run_.bodies_at_t()[1]; }

  // Which bottom corner of the box a contact is at, in the box's frame at t: −1 or +1.
  double corner_side(const ContactInfo& c) const {
    const RigidBody& box = box_at_t();
    return std::copysign(1.0, (box.rotation.transpose() * (contact_corner(c) - box.x)).x());
  }

  // "a" for the corner of the first contact, "b" for the other.
  std::string corner_name(const ContactInfo& c) const {
    return corner_side(c) == first_corner_ ? "a" : "b";
  }

  void observe() {
    const std::vector<ContactInfo> contacts = run_.report().contacts();
    if (contacts.empty()) return;
    if (frames_in_contact_ == 0) first_corner_ = corner_side(contacts[0]);
    ++frames_in_contact_;
  }

  bool cache_;
  view::SteppedWorld run_;
  int frames_in_contact_ = 0;  // steps solved with at least one contact
  double first_corner_ = 0.0;  // side (−1, +1) of corner a, the first contact's
};

void draw_ground(render::Frame& frame) { frame.grounds.push_back({Vec2::Zero(), Vec2::UnitY()}); }

tutorial::Explanation titled(const std::string& prefix, tutorial::Explanation e) {
  for (tutorial::Section& s : e) s.title = prefix + s.title;
  return e;
}

// Fig 4-2..4-5 as one full-width story.
class Landing : public tutorial::Scene {
 public:
  explicit Landing(const tutorial::Options& o) : run_(!o.no_cache) {}

  tutorial::SceneInfo info() const override {
    return {"landing", dt, 100, 1, {Vec2(-3.4, -1.2), Vec2(3.4, 2.8)}};
  }
  void step() override { run_.step(); }

  void draw(render::Frame& frame) const override {
    frame.caption = run_.moment();
    frame.force_scale = force_scale;
    draw_ground(frame);
    run_.draw(frame, 0.0, colour());
    frame.panels.push_back(run_.panel(render::Corner::bottom_left, colour()));
    frame.legend_corner = render::Corner::top_right;
  }

  tutorial::Explanation explain() const override { return run_.explain(); }

 private:
  render::Colour colour() const {
    return run_.cache() ? render::palette::blue : render::palette::vermillion;
  }
  DropRun run_;
};

// The same drop twice: cache on (left) and off (right); the penetration plot.
class CacheOnVsOff : public tutorial::Scene {
 public:
  static constexpr double offset = 1.8;  // each drop's x distance from the frame's middle, in m

  CacheOnVsOff() : runs_{DropRun(true), DropRun(false)} {}

  tutorial::SceneInfo info() const override {
    return {"cache_on_vs_off", dt, 100, 1, {Vec2(-5.4, -1.5), Vec2(5.4, 2.9)}};
  }
  void step() override {
    for (DropRun& run : runs_) run.step();
  }

  void draw(render::Frame& frame) const override {
    frame.caption = "Fig 4-2..4-5 · the same landing with the contact cache (left) and without";
    frame.force_scale = force_scale;
    draw_ground(frame);
    runs_[0].draw(frame, -offset, render::palette::blue);
    runs_[1].draw(frame, offset, render::palette::vermillion);
    frame.panels.push_back(runs_[0].panel(render::Corner::bottom_left, render::palette::blue));
    frame.panels.push_back(
        runs_[1].panel(render::Corner::bottom_right, render::palette::vermillion));
    frame.paths.push_back({{Vec2(0.0, 0.0), Vec2(0.0, 2.9)},
                           render::palette::grid, false});
    frame.legend_corner = render::Corner::top_right;
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e = titled("cache on · ", runs_[0].explain());
    const tutorial::Explanation off = titled("cache off · ", runs_[1].explain());
    e.insert(e.end(), off.begin(), off.end());
    return e;
  }

  // penetration.png over 4 s, whatever --frames rendered.
  void write_data(const std::filesystem::path& folder) const override {
    constexpr int steps = 240;
    std::array<World, 2> worlds{drop_world(true), drop_world(false)};
    std::vector<std::vector<double>> rows;
    for (int s = 0; s <= steps; ++s) {
      if (s > 0) {
        for (World& w : worlds) w.step();
      }
      rows.push_back({s * dt, 1000.0 * penetration(worlds[0].bodies()[1]),
                      1000.0 * penetration(worlds[1].bodies()[1]), 1000.0 * worlds[0].settings().contact.slop});
    }
    tutorial::write_plot(folder, {"penetration",
                                  "Tilted box landing: its deepest corner below the ground",
                                  "t (s)",
                                  "penetration (mm)",
                                  {{"cache on", render::palette::blue, false},
                                   {"cache off", render::palette::vermillion, false},
                                   {"slop (left uncorrected)", render::palette::grey, true}},
                                  rows,
                                  "top right"});
  }

 private:
  std::array<DropRun, 2> runs_;
};

}  // namespace

int main(int argc, char** argv) {
  tutorial::TutorialInfo info{
      "04_contact_model",
      "ch4",
      "Chapter 4: the contact cache of Fig 4-2..4-5 (a tilted box landing, cache on vs off) and a "
      "friction ramp, with the penetration plot",
      {render::Overlay::contacts, render::Overlay::normals, render::Overlay::forces,
       render::Overlay::centres}};
  info.has_cache = true;
  return tutorial::run_tutorial(
      argc, argv, info,
      {[](const tutorial::Options& o) { return std::make_unique<Landing>(o); },
       tutorial::scene<CacheOnVsOff>(), ch4::friction_ramp_scene()});
}
