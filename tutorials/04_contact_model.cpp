// Chapter 4 — the contact model. Three scenes, each frame showing the bodies at t with the
// contacts the step from t found and the λ it solved for them:
//   landing          Fig 4-2..4-5: a unit box dropped tilted by 0.3 rad lands on one corner a,
//                    turns, corner b goes in while a is still cached, and it rests on both
//                    (--no-cache: the same drop without the cache, which never rests);
//   cache_on_vs_off  the same drop twice side by side, with and without the contact cache, and
//                    the plot penetration.png (deepest corner below the ground against t);
//   friction_ramp    a box that sticks (tan θ < μ) and one that slides at g (sin θ − μ cos θ)
//                    (--no-cache: without the cache).
// The scene is the docs' (docs/ch4-contact-model.md): ground half extents (20, 0.5), top at y = 0.
#include <algorithm>
#include <array>
#include <cmath>

#include "contact_views.h"
#include "harness/format.h"
#include "harness/plot.h"
#include "harness/tutorial.h"

namespace {

using namespace lamina;
using tutorial::fixed;
using Vec2r = render::Vec2;

constexpr double dt = 1.0 / 60.0;       // Δt, in s (WorldSettings' default)
constexpr double g = 9.8;               // |g|, in m/s²
constexpr double drop_tilt = 0.3;       // θ(0) of the dropped box, in rad
const Vec3 drop_start(0.0, 2.0, 0.0);   // x(0) of the dropped box, in m
const Material drop_material{0.6, 0.0}; // μ = 0.6, e = 0 (the Box2D comparison's)
constexpr double force_scale = 0.1;     // arrow length per λ, in m per N
constexpr double longest_force = 16.0;  // forces above this (landing impacts) are drawn cut, in N
constexpr double at_rest = 1e-2;        // |v| (m/s) and |ω| (rad/s) below this count as resting

WorldSettings with_cache(bool cache) {
  WorldSettings settings;
  settings.cache.enabled = cache;
  return settings;
}

// The docs' scene: the ground (body 0), then the unit box of 1 kg dropped tilted (body 1).
void add_drop(World& world) {
  world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, drop_material);
  world.add_box(1.0, 0.5, 0.5, drop_start, drop_tilt, drop_material);
}

// How deep the box's lowest corner is below the ground's top y = 0, in m (0 when above).
double penetration(const RigidBody& box) {
  const double angle = planar_angle(box.q);
  const double reach = 0.5 * std::abs(std::sin(angle)) + 0.5 * std::abs(std::cos(angle));
  return std::max(0.0, reach - box.x.y());
}

// Landing impacts are tens of times the weight: an arrow longer than `longest_force` is drawn
// at that length, and a label `offset` from its tip gives the force.
void cut_arrow(render::Frame& frame, const Vec2r& from, const Vec2r& direction, double& force,
               const std::string& symbol, render::Colour colour, const Vec2r& offset) {
  if (std::abs(force) <= longest_force) return;
  const Vec2r tip = from + force_scale * std::copysign(longest_force, force) * direction;
  frame.labels.push_back({tip + offset, symbol + " = " + fixed(force, 0) + " N (arrow cut)",
                          colour, render::Label::Align::left});
  force = std::copysign(longest_force, force);
}

// Roughly where a contact's corner is: the point lies midway between the corner and the ground's
// surface, so the corner is near c + (C/2) n (exactly for a fresh point).
Vec3 contact_corner(const ContactInfo& c) { return c.point + 0.5 * c.separation * c.normal; }

// One run of the tilted drop and what the story has seen so far.
class DropRun {
 public:
  explicit DropRun(bool cache) : cache_(cache), run_(with_cache(cache)) {
    add_drop(run_.world());
    run_.solve();
    observe();
  }

  void step() {
    run_.solve();
    observe();
  }

  const tutorial::SolvedWorld& solved() const { return run_; }
  bool cache() const { return cache_; }

  // Draws the ground-less part of the run (box, contacts, corner names), shifted by `dx` in x.
  void draw(render::Frame& frame, double dx, render::Colour colour) const {
    const Vec2r shift(dx, 0.0);
    render::Body box = tutorial::body_view(run_, 1, tint(colour, 0.35));
    box.centre += shift;
    frame.bodies.push_back(box);
    for (const ContactInfo& c : run_.report().contacts) {
      render::Contact view = tutorial::contact_view(c);
      view.point += shift;
      cut_arrow(frame, view.point, view.normal, view.normal_force, "λ_n",
                render::palette::bluish_green, Vec2r(0.08, 0.0));
      cut_arrow(frame, view.point, view.tangent, view.friction_force, "λ_t",
                render::palette::orange, Vec2r(0.0, -0.2));
      frame.contacts.push_back(view);
      const bool left = corner_side(c) < 0.0;
      frame.labels.push_back({view.point + Vec2r(left ? -0.14 : 0.14, 0.1), corner_name(c),
                              render::palette::ink,
                              left ? render::Label::Align::right : render::Label::Align::left});
    }
  }

  // The run's numbers: pose, spin, and each contact with its C and λ.
  render::Panel panel(render::Corner corner, render::Colour colour) const {
    const RigidBody& box = run_.bodies()[1];
    render::Panel p;
    p.corner = corner;
    p.title = cache_ ? "cache on" : "cache off";
    p.title_colour = colour;
    p.lines = {"θ = " + fixed(planar_angle(box.q), 3) + " rad   ω = " +
                   fixed(box.angular_velocity.z(), 2) + " rad/s",
               "penetration = " + fixed(1000.0 * penetration(box), 1) + " mm"};
    double total = 0.0, friction = 0.0;
    for (const ContactInfo& c : run_.report().contacts) {
      p.lines.push_back(corner_name(c) + (c.cached ? " cached" : " fresh ") +
                        "  C = " + fixed(c.separation, 4) + " m  λ_n = " +
                        fixed(c.lambda_normal, 1) + " N  λ_t = " + fixed(c.lambda_tangent, 1) +
                        " N");
      total += c.lambda_normal;
      friction += c.lambda_tangent;
    }
    if (run_.report().contacts.empty()) p.lines.push_back("no contact: falling under m g");
    p.lines.push_back("Σ λ_n = " + fixed(total, 2) + " N (m g = " + fixed(g, 2) + " N), Σ λ_t = " +
                      fixed(friction, 2) + " N");
    return p;
  }

  // The moment of the story the run is at, in the figures' words.
  std::string moment() const {
    const std::vector<ContactInfo>& contacts = run_.report().contacts;
    const RigidBody& box = run_.bodies()[1];
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
  // Which bottom corner of the box a contact is at, in the box's frame at t: −1 or +1.
  double corner_side(const ContactInfo& c) const {
    const RigidBody& box = run_.bodies()[1];
    return std::copysign(1.0, (box.rotation.transpose() * (contact_corner(c) - box.x)).x());
  }

  // "a" for the corner of the first contact, "b" for the other.
  std::string corner_name(const ContactInfo& c) const {
    return corner_side(c) == first_corner_ ? "a" : "b";
  }

  void observe() {
    const std::vector<ContactInfo>& contacts = run_.report().contacts;
    if (contacts.empty()) return;
    if (frames_in_contact_ == 0) first_corner_ = corner_side(contacts[0]);
    ++frames_in_contact_;
  }

  bool cache_;
  tutorial::SolvedWorld run_;
  int frames_in_contact_ = 0;  // steps solved with at least one contact
  double first_corner_ = 0.0;  // side (−1, +1) of corner a, the first contact's
};

void draw_ground(render::Frame& frame) { frame.grounds.push_back({Vec2r::Zero(), Vec2r::UnitY()}); }

tutorial::Explanation titled(const std::string& prefix, tutorial::Explanation e) {
  for (tutorial::Section& s : e) s.title = prefix + s.title;
  return e;
}

// Fig 4-2..4-5 as one full-width story.
class Landing : public tutorial::Scene {
 public:
  explicit Landing(const tutorial::Options& o) : run_(!o.no_cache) {}

  tutorial::SceneInfo info() const override {
    return {"landing", dt, 100, 1, {Vec2r(-3.4, -1.2), Vec2r(3.4, 2.8)}};
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

  tutorial::Explanation explain() const override { return tutorial::explain_solved(run_.solved()); }

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
    return {"cache_on_vs_off", dt, 100, 1, {Vec2r(-5.4, -1.5), Vec2r(5.4, 2.9)}};
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
    frame.paths.push_back({{Vec2r(0.0, 0.0), Vec2r(0.0, 2.9)},
                           render::palette::grid, false});
    frame.legend_corner = render::Corner::top_right;
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e = titled("cache on · ", tutorial::explain_solved(runs_[0].solved()));
    const tutorial::Explanation off =
        titled("cache off · ", tutorial::explain_solved(runs_[1].solved()));
    e.insert(e.end(), off.begin(), off.end());
    return e;
  }

  // penetration.png over 4 s, whatever --frames rendered.
  void write_data(const std::filesystem::path& folder) const override {
    constexpr int steps = 240;
    std::array<World, 2> worlds{World(with_cache(true)), World(with_cache(false))};
    for (World& w : worlds) add_drop(w);
    std::vector<std::vector<double>> rows;
    for (int s = 0; s <= steps; ++s) {
      if (s > 0) {
        for (World& w : worlds) w.step();
      }
      rows.push_back({s * dt, 1000.0 * penetration(worlds[0].bodies()[1]),
                      1000.0 * penetration(worlds[1].bodies()[1]), 1000.0 * with_cache(true).contact.slop});
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

// A box on a ramp of angle θ: it sticks when tan θ < μ and slides at g (sin θ − μ cos θ) else.
struct Ramp {
  double theta;          // θ, in rad
  Vec3 centre;           // the ramp's centre, in m
  render::Colour colour;
  render::Corner corner;  // where its panel goes
};

class FrictionRamp : public tutorial::Scene {
 public:
  static constexpr double mu = 0.5;          // μ of both materials, so the pair's √(μ1 μ2) = 0.5
  static constexpr double half_length = 2.6; // ramp half length, in m
  static constexpr double half_thickness = 0.15;
  static constexpr double start = 1.6;       // the box's start up the slope from the centre, in m
  inline static const Vec2r box_half{0.35, 0.25};

  explicit FrictionRamp(const tutorial::Options& o)
      : ramps_{Ramp{20.0 * M_PI / 180.0, Vec3(-3.4, 0.6, 0.0), render::palette::bluish_green,
                    render::Corner::bottom_left},
               Ramp{35.0 * M_PI / 180.0, Vec3(3.4, 0.8, 0.0), render::palette::vermillion,
                    render::Corner::bottom_right}},
        world_(with_cache(!o.no_cache)) {
    const Material material{mu, 0.0};
    for (const Ramp& r : ramps_) {
      world_.world().add_static_box(half_length, half_thickness, r.centre, r.theta, material);
      const Vec3 up_slope(std::cos(r.theta), std::sin(r.theta), 0.0);
      const Vec3 normal(-std::sin(r.theta), std::cos(r.theta), 0.0);
      world_.world().add_box(1.0, box_half.x(), box_half.y(),
                             r.centre + start * up_slope + (half_thickness + box_half.y()) * normal,
                             r.theta, material);
    }
    world_.solve();
  }

  tutorial::SceneInfo info() const override {
    return {"friction_ramp", dt, 90, 1, {Vec2r(-6.4, -2.3), Vec2r(6.4, 3.2)}};
  }
  void step() override { world_.solve(); }

  void draw(render::Frame& frame) const override {
    frame.caption = "Friction rows, bounds ±μ λc: sticks when tan θ < μ, slides when tan θ > μ";
    frame.force_scale = 0.35;
    for (std::size_t i = 0; i < ramps_.size(); ++i) {
      const int ramp = static_cast<int>(2 * i), box = ramp + 1;
      frame.bodies.push_back(tutorial::body_view(world_, ramp, render::palette::grid));
      frame.bodies.push_back(tutorial::body_view(world_, box, tint(ramps_[i].colour, 0.35)));
      frame.panels.push_back(panel(i));
    }
    for (const ContactInfo& c : world_.report().contacts) {
      frame.contacts.push_back(tutorial::contact_view(c));
    }
    frame.legend_corner = render::Corner::top_left;
  }

  tutorial::Explanation explain() const override { return tutorial::explain_solved(world_); }

 private:
  render::Panel panel(std::size_t i) const {
    const Ramp& r = ramps_[i];
    const int box = static_cast<int>(2 * i + 1);
    const Vec3 down_slope(-std::cos(r.theta), -std::sin(r.theta), 0.0);
    const RigidBody& at_t = world_.bodies()[static_cast<std::size_t>(box)];
    const RigidBody& after = world_.world().bodies()[static_cast<std::size_t>(box)];
    const double measured = (after.v - at_t.v).dot(down_slope) / dt;
    // The text's sliding box: m a = m g sin θ − μ m g cos θ along the slope.
    const double predicted = g * (std::sin(r.theta) - mu * std::cos(r.theta));
    double normal = 0.0, friction = 0.0;
    for (const ContactInfo& c : world_.report().contacts) {
      if (c.bodies.second != box) continue;
      normal += c.lambda_normal;
      friction += c.lambda_tangent;
    }
    const bool slides = std::tan(r.theta) > mu;
    render::Panel p;
    p.corner = r.corner;
    p.title = "θ = " + fixed(r.theta * 180.0 / M_PI, 0) + "°: tan θ = " +
              fixed(std::tan(r.theta), 3) + (slides ? " > μ = " : " < μ = ") + fixed(mu, 1) +
              (slides ? ", slides" : ", sticks");
    p.title_colour = r.colour;
    p.lines = {"g (sin θ − μ cos θ) = " + fixed(predicted, 3) + " m/s²" +
                   (slides ? "" : " < 0: friction holds"),
               "a along the slope = " + fixed(measured, 3) + " m/s² (solved)",
               "v along the slope = " + fixed(after.v.dot(down_slope), 3) + " m/s",
               "|Σ λ_t| = " + fixed(std::abs(friction), 3) + " N,  μ Σ λ_n = " +
                   fixed(mu * normal, 3) + " N"};
    return p;
  }

  std::array<Ramp, 2> ramps_;
  tutorial::SolvedWorld world_;
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
       tutorial::scene<CacheOnVsOff>(),
       [](const tutorial::Options& o) { return std::make_unique<FrictionRamp>(o); }});
}
