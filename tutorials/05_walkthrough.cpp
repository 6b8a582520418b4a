// Chapter 5 — the walk-through, run. Box A (1 m, 1 kg) at rest, turned by 0.005 rad so that its
// corner a is 0.01 m into the fixed ground B; the text's method: Baumgarte bias (β = 0.2, no
// slop) and no friction, so the MLCP is exactly eq. 5-8 (one row at t = τ) and eq. 5-19 (two rows,
// the cached a and the fresh b, at t = τ + Δt). Each frame shows the state at t with what the step
// from t solved: M⁻¹, F_ext, V, x_a, ε, ζ, J, λ, f_c, τ_c (eq. 5-1..5-21), and two insets that
// magnify the corners. normal_force.png shows Σ λ converging to m g (t → ∞).
// The text has z up (N = (0, 0, 1)); Lamina, like Box2D, has y up (N = (0, 1, 0)).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "app/harness/format.h"
#include "app/harness/plot.h"
#include "app/harness/tutorial.h"
#include "app/views/contact/stepped_world.h"
#include "app/views/contact/world_explanation.h"
#include "app/views/contact/world_view.h"

namespace {

using namespace lamina;
using tutorial::fixed;

constexpr double tilt = 0.005;    // θ1(τ), in rad
constexpr double depth = 0.01;    // how deep corner a starts, in m
constexpr double magnify = 20.0;  // the corner insets' magnification
constexpr double inset_half = 0.3;  // half the side of an inset, in m of the frame
constexpr double at_rest = 1e-3;    // |v| (m/s) and |ω| (rad/s) below this: t → ∞

// The text's method: Baumgarte bias with no slop, frictionless (chapter 5 has no friction).
WorldSettings text_settings() {
  WorldSettings settings;
  settings.contact.correction = PositionCorrection::baumgarte;
  settings.contact.slop = 0.0;
  return settings;
}

// Fig 5-1: the ground B (body 0) and box A (body 1) with corner a `depth` into the ground.
World walkthrough_world() {
  World world(text_settings());
  const Material frictionless{0.0, 0.0};
  world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, frictionless);
  const double lowest = 0.5 * std::cos(tilt) + 0.5 * std::sin(tilt);  // corner a below x1
  world.add_box(1.0, 0.5, 0.5, Vec3(0.0, lowest - depth, 0.0), tilt, frictionless);
  return world;
}

// A number for J's entries: "0" for an exact zero, else 4 significant digits.
std::string entry(double x) {
  if (x == 0.0) return "0";
  char text[16];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

// "(x, y)" with fixed decimals.
std::string pair_text(const Vec3& v, int decimals) {
  return "(" + fixed(v.x(), decimals) + ", " + fixed(v.y(), decimals) + ")";
}

// A segment clipped to the square |p − centre|∞ ≤ half (Liang–Barsky); false when outside.
bool clip(Vec2& a, Vec2& b, const Vec2& centre, double half) {
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    for (double side : {-1.0, 1.0}) {
      const double p = side * d[axis], q = half - side * (a[axis] - centre[axis]);
      if (p == 0.0) {
        if (q < 0.0) return false;
        continue;
      }
      const double t = q / p;
      if (p < 0.0) t0 = std::max(t0, t);
      if (p > 0.0) t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return false;
  const Vec2 start = a;
  a = start + t0 * d;
  b = start + t1 * d;
  return true;
}

class Walkthrough : public tutorial::Scene {
 public:
  Walkthrough() : run_(walkthrough_world()) { run_.step(); }

  tutorial::SceneInfo info() const override {
    return {"walkthrough", run_.world().settings().step.dt, 120, 1,
            {Vec2(-3.45, -0.42), Vec2(0.95, 2.0)}};
  }
  void step() override { run_.step(); }

  void draw(render::Frame& frame) const override {
    frame.caption = "Ch 5 walk-through · " + moment();
    frame.force_scale = 0.05;
    frame.grounds.push_back({Vec2::Zero(), Vec2::UnitY()});
    frame.bodies.push_back(view::body_view(box(), run_.world().shape(1), tint(render::palette::sky_blue, 0.35)));
    for (std::size_t i = 0; i < run_.report().contacts().size(); ++i) {
      const ContactInfo c = run_.report().contacts()[i];
      frame.contacts.push_back(view::contact_view(c));
      const bool a = corner_name(i) == "a";
      frame.labels.push_back({c.point.head<2>() + Vec2(a ? -0.06 : 0.06, -0.13),
                              corner_name(i) + ": λ = " + fixed(c.lambda_normal, 2) + " N",
                              render::palette::ink,
                              a ? render::Label::Align::right : render::Label::Align::left});
    }
    for (double side : {-1.0, 1.0}) draw_inset(frame, side);
    frame.panels.push_back(panel());
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e = view::explain_world_step(run_.world(), run_.report(), {"ground B", "box A"});
    e.insert(e.begin(), walkthrough_section());
    return e;
  }

  // normal_force.png: Σ λ over 2 s against m g.
  void write_data(const std::filesystem::path& folder) const override {
    World world = walkthrough_world();
    const double dt = world.settings().step.dt;
    const double weight = world.bodies()[1].mass * -world.settings().step.gravity.y();
    std::vector<std::vector<double>> rows;
    for (int s = 0; s < 120; ++s) {
      WorldReport report;
      world.step(report);
      const Vec6 wrench = report.velocity.constraint_wrench(1);
      rows.push_back({s * dt, wrench[1], wrench[5], weight});
    }
    tutorial::write_plot(folder, {"normal_force",
                                  "Walk-through: the contact force on box A converges to m g",
                                  "t − τ (s)",
                                  "f_c1,y (N), τ_c1 (N·m)",
                                  {{"f_c1,y = Σ λ_i N_y (eq. 5-9)", render::palette::blue, false},
                                   {"τ_c1 (eq. 5-9)", render::palette::orange, false},
                                   {"m1 g", render::palette::ink, true}},
                                  rows});
  }

 private:
  const RigidBody& box() const { return run_.bodies_at_t()[1]; }
  long step_index() const { return run_.step_index(); }  // steps since τ
  const Contact& contact(std::size_t i) const { return run_.report().pairs.at(0).contacts.at(i); }

  bool resting() const {
    return step_index() > 2 && box().v.norm() < at_rest && std::abs(box().angular_velocity.z()) < at_rest;
  }

  std::string moment() const {
    switch (step_index()) {
      case 0: return "t = τ: one row, the deepest corner a (eq. 5-1..5-11)";
      case 1: return "t = τ + Δt: a from the cache, b fresh, J is 2 × 12 (eq. 5-12..5-21)";
      case 2: return "t = τ + 2Δt: both corners again, the forces nearly equal";
      default:
        return resting() ? "t → ∞: f_c1 = m1 g, τ_c1 = 0, each corner carries 4.9 N"
                         : "settling: both corners kept in the cache";
    }
  }

  // r = R1ᵀ (x − x1) of contact i, the anchor the cache keeps in the box's frame (eq. 5-12).
  Vec3 anchor(std::size_t i) const {
    const Vec2 r = contact(i).anchor[1];
    return Vec3(r.x(), r.y(), 0.0);
  }

  // x = x1 + R1 r of contact i: the box's corner at t (eq. 5-12).
  Vec3 corner(std::size_t i) const { return box().x + box().rotation * anchor(i); }

  // "a" for the corner on the −x side of the box (the text's first contact), "b" for the other.
  std::string corner_name(std::size_t i) const { return anchor(i).x() < 0.0 ? "a" : "b"; }

  // The index of the contact at corner `side` (−1: a, +1: b), or −1.
  int contact_at(double side) const {
    for (std::size_t i = 0; i < run_.report().contacts().size(); ++i) {
      if ((corner_name(i) == "a") == (side < 0.0)) return static_cast<int>(i);
    }
    return -1;
  }

  // Corner `side` (−1: a, +1: b) magnified `magnify` times in a square above the box.
  void draw_inset(render::Frame& frame, double side) const {
    const Vec2 centre(side * 0.55, 1.52);
    const Vec3 at_corner = box().x + box().rotation * Vec3(side * 0.5, -0.5, 0.0);
    const Vec2 focus(at_corner.x(), 0.0);  // the ground's surface under the corner
    auto map = [&](const Vec3& p) { return Vec2(centre + magnify * (p.head<2>() - focus)); };
    auto segment = [&](Vec2 a, Vec2 b, render::Colour colour, bool dashed) {
      if (clip(a, b, centre, inset_half)) frame.paths.push_back({{a, b}, colour, dashed});
    };
    const Vec2 h(inset_half, inset_half), k(inset_half, -inset_half);
    frame.paths.push_back(
        {{centre - h, centre - k, centre + h, centre + k, centre - h}, render::palette::grey, false});
    segment(map(Vec3(focus.x() - 1.0, 0.0, 0.0)), map(Vec3(focus.x() + 1.0, 0.0, 0.0)),
            render::palette::ink, false);
    for (int i = -4; i <= 4; ++i) {  // the ground's hatching
      const Vec2 top = centre + Vec2(0.15 * i, 0.0);
      segment(top, top + Vec2(-0.4, -0.4), render::palette::grid, false);
    }
    for (int i = 0; i < 4; ++i) {
      const Vec3 r0(i == 0 || i == 3 ? -0.5 : 0.5, i < 2 ? -0.5 : 0.5, 0.0);
      const Vec3 r1(i == 0 || i == 1 ? 0.5 : -0.5, i == 0 || i == 3 ? -0.5 : 0.5, 0.0);
      segment(map(box().x + box().rotation * r0), map(box().x + box().rotation * r1),
              render::palette::blue, false);
    }
    std::string text;
    if (const int i = contact_at(side); i >= 0) {
      const ContactInfo contact = run_.report().contacts()[static_cast<std::size_t>(i)];
      const ContactInfo* c = &contact;
      const Vec2 at = map(c->point);
      frame.paths.push_back({{at + Vec2(-0.03, 0.0), at + Vec2(0.03, 0.0)},
                             render::palette::vermillion, false});
      frame.paths.push_back({{at + Vec2(0.0, -0.03), at + Vec2(0.0, 0.03)},
                             render::palette::vermillion, false});
      text = "ε = " + fixed(std::min(c->separation, 0.0), 4) + " m" +
             (c->cached ? " (cached)" : " (fresh)");
    } else if (at_corner.y() < 0.0) {
      text = "ε = " + fixed(at_corner.y(), 4) + " m, not found: only the deepest";
    } else {
      text = "no contact";
    }
    frame.labels.push_back({centre + Vec2(0.0, inset_half + 0.08),
                            std::string(side < 0.0 ? "corner a" : "corner b") + " ×" +
                                fixed(magnify, 0),
                            render::palette::ink, render::Label::Align::centre});
    frame.labels.push_back({centre - Vec2(0.0, inset_half + 0.08), text, render::palette::ink,
                            render::Label::Align::centre});
  }

  // The text's J row of a contact: the box block [Nᵀ ((x − x1) × N)ᵀ], then the ground's 0ᵀ 0ᵀ.
  std::string j_row(std::size_t i) const {
    const Vec6 box_block = run_.report().velocity.mlcp.jacobian(contact(i).row, 0);
    std::string text = "[";
    for (int c = 0; c < 6; ++c) text += (c ? " " : "") + entry(box_block[c]);
    return text + " | 0 0 0 0 0 0]";
  }

  render::Panel panel() const {
    const WorldReport& report = run_.report();
    const double beta = run_.world().settings().step.beta;
    const Vec6 wrench = report.velocity.constraint_wrench(1);
    const int rows = report.velocity.mlcp.row_count();
    render::Panel p;
    p.corner = render::Corner::top_left;
    p.title = "step " + std::to_string(step_index()) + ": rows s = " + std::to_string(rows) +
              ", J is " + std::to_string(rows) + " × 12";
    p.lines = {"M⁻¹ = diag(m1⁻¹E, I1⁻¹, 0, 0): m1⁻¹ = " + fixed(box().inverse_mass, 1) +
                   ", I1⁻¹ = " + fixed(box().inverse_inertia_world(2, 2), 1) + "  (5-1)",
               "F_ext = [m1 g, 0, 0, 0], m1 g = " +
                   pair_text(box().mass * run_.world().settings().step.gravity, 1) + " N  (5-2)",
               "V: v1 = " + pair_text(box().v, 4) + " m/s, ω1 = " +
                   fixed(box().angular_velocity.z(), 4) + " rad/s  (5-3)"};
    for (std::size_t i = 0; i < report.contacts().size(); ++i) {
      const ContactInfo c = report.contacts()[i];
      const std::string n = corner_name(i);
      const double epsilon = std::min(c.separation, 0.0);
      p.lines.push_back(n + (c.cached ? " cached" : " fresh") + ": x_" + n + " = " +
                        pair_text(corner(i), 4) + ", r_" + n + " = " + pair_text(anchor(i), 2) +
                        "  (5-12)");
      p.lines.push_back("  ε = " + fixed(epsilon, 5) + " m, ζ = −β ε = " +
                        fixed(-beta * epsilon, 5) + " m  (5-6)");
      p.lines.push_back("  J = " + j_row(i) + "  (5-8)");
      p.lines.push_back("  λ = " + fixed(report.velocity.solution.lambda[contact(i).row], 4) +
                        " N  (5-9..5-11, 5-21)");
    }
    p.lines.push_back("f_c1 = " + pair_text(Vec3(wrench.head<3>()), 4) + " N, τ_c1 = " +
                      fixed(wrench[5], 4) + " N·m  (5-9)");
    p.lines.push_back("text: z up, N = (0, 0, 1); Lamina: y up, N = (0, 1, 0)");
    return p;
  }

  // The text's quantities of this step, for --explain.
  tutorial::Section walkthrough_section() const {
    const WorldReport& report = run_.report();
    const double beta = run_.world().settings().step.beta;
    const Vec6 wrench = report.velocity.constraint_wrench(1);
    tutorial::Section s{"walk-through (the text has z up, N = (0, 0, 1); Lamina y up, N = (0, 1, 0))",
                        {}};
    for (std::size_t i = 0; i < report.contacts().size(); ++i) {
      const ContactInfo c = report.contacts()[i];
      const std::string n = corner_name(i);
      const double epsilon = std::min(c.separation, 0.0);
      s.quantities.push_back({"x_" + n, "5-12", c.cached ? "corner x1 + R1 r, re-placed from the cache"
                                                         : "corner, fresh (deepest point)",
                              tutorial::json_of(corner(i)), "m"});
      s.quantities.push_back({"r_" + n, "5-12", "R1ᵀ (x_" + n + " − x1), box frame",
                              tutorial::json_of(anchor(i)), "m"});
      s.quantities.push_back({"ε_" + n, "5-6", "min(N·x_" + n + " − N·c, 0)", epsilon, "m"});
      s.quantities.push_back({"ζ_" + n, "5-6", "−β ε", -beta * epsilon, "m"});
    }
    s.quantities.push_back({"f_c1", "5-9", "Σ λ_i N", tutorial::json_of(Vec3(wrench.head<3>())), "N"});
    s.quantities.push_back({"τ_c1", "5-9", "Σ (x_i − x1) × λ_i N", tutorial::json_of(Vec3(wrench.tail<3>())),
                            "N·m"});
    return s;
  }

  view::SteppedWorld run_;
};

}  // namespace

int main(int argc, char** argv) {
  const tutorial::TutorialInfo info{
      "05_walkthrough",
      "ch5",
      "Chapter 5: the walk-through at t = τ, τ+Δt, τ+2Δt and t → ∞ with the numbers of eq. "
      "5-1..5-21, and the normal force converging to m g",
      {render::Overlay::contacts, render::Overlay::normals, render::Overlay::forces,
       render::Overlay::centres}};
  return tutorial::run_tutorial(argc, argv, info, {tutorial::scene<Walkthrough>()});
}
