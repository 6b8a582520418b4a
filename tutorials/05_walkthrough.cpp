// Chapter 5 — the walk-through, run by the text's own method (--solver text: Baumgarte's bias with
// β = 0.2 and no slop, the contact cache, no friction in chapter 5). Box A (1 m, 1 kg) at rest,
// turned by 0.005 rad so that its corner a is 0.01 m into the fixed ground B; box A is body 1 and
// the ground body 2, in the text's order, so M⁻¹ = diag(m1⁻¹E, I1⁻¹, 0, 0) and J = [J_A | 0 0].
// At t = τ the MLCP is one row (eq. 5-8), at t = τ + Δt two, the cached a and the fresh b
// (eq. 5-19). Each frame shows the state at t with what the step from t solved, tagged with the
// text's equations (eq. 5-1..5-21): M⁻¹, F_ext, V, each corner's x, N·v (5-4, 5-5), ε and ζ,
// J, the bounds and λ, f_c and τ_c; two insets magnify the corners. At t = τ it also shows λ1
// as eq. 5-7 reads literally (ζ, a length, as a velocity). normal_force.png shows Σ λ converging
// to m g (t → ∞). The text has z up (N = (0, 0, 1)); Lamina, like Box2D, has y up (N = (0, 1, 0)).
#include <cmath>
#include <cstdio>
#include <string>

#include "app/harness/format.h"
#include "app/harness/plot.h"
#include "app/harness/tutorial.h"
#include "app/views/contact/stepped_world.h"
#include "app/views/contact/world_explanation.h"
#include "app/views/contact/world_view.h"
#include "ch5/corner_inset.h"
#include "contact/solvers.h"
#include "language/language.h"

namespace {

using namespace lamina;
using tutorial::fixed;
using tutorial::counted;

constexpr double tilt = 0.005;   // θ1(τ), in rad
constexpr double depth = 0.01;   // how deep corner a starts, in m
constexpr int box_a = 0;         // body 1 of the text
constexpr double at_rest = 1e-3; // |v| (m/s) and |ω| (rad/s) below this: t → ∞
const Vec3 N(0.0, 1.0, 0.0);     // the ground's normal; the contact plane is N·x ≥ N·c, N·c = 0

// Fig 5-1: box A (body 1 of the text, here index 0) with corner a `depth` into the fixed ground
// B, stepped by `solver` (the text's method unless --solver says otherwise) with bias β.
World walkthrough_world(double beta, const std::string& solver) {
  WorldSettings settings = with_solver(WorldSettings(), solver);
  settings.step.beta = beta;
  World world(settings);
  const Material frictionless{0.0, 0.0};
  const double lowest = 0.5 * std::cos(tilt) + 0.5 * std::sin(tilt);  // corner a below x1
  world.add_box(1.0, 0.5, 0.5, Vec3(0.0, lowest - depth, 0.0), tilt, frictionless);
  world.add_static_box(20.0, 0.5, Vec3(0.0, -0.5, 0.0), 0.0, frictionless);
  return world;
}

// λ1 at t = τ as eq. 5-7 reads literally: N·v_a ≥ ζ1 with ζ1 = −β ε, a length, taken as the
// velocity. Lamina asks ζ1/Δt (eq. 4-5); the literal reading is Lamina's step with β Δt for β.
double literal_lambda() {
  const double beta = StepSettings().beta, dt = StepSettings().dt;
  World world = walkthrough_world(beta * dt, "text");
  WorldReport report;
  world.step(report);
  return report.velocity.solution.lambda[0];
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

// The text's equation numbers for the rows of step k: t = τ has one row (eq. 5-6..5-11); from
// t = τ + Δt on, a cached a and a fresh b (eq. 5-12..5-21).
struct RowTags {
  const char* zeta;
  const char* J;
  const char* bounds;
};
RowTags tags_of(long step, bool second) {
  if (step == 0) return {"5-6", "5-8", "5-10"};
  return second ? RowTags{"5-16", "5-17", "5-18"} : RowTags{"5-13", "5-14", "5-15"};
}

// The contact's origin as the panel names it: origin_name's words, in the frame's language.
const char* origin_text(ContactOrigin origin) {
  switch (origin) {
    case ContactOrigin::fresh: return tr("new");
    case ContactOrigin::refound: return tr("refound");
    case ContactOrigin::kept: return tr("kept");
  }
  return origin_name(origin);
}

class Walkthrough : public tutorial::Scene {
 public:
  explicit Walkthrough(const tutorial::Options& o)
      : solver_(o.solver.value_or("text")),
        run_(walkthrough_world(StepSettings().beta, solver_)),
        literal_(literal_lambda()) {
    run_.step();
  }

  tutorial::SceneInfo info() const override {
    return {"walkthrough", run_.world().settings().step.dt, 120, 1,
            {Vec2(-3.45, -0.78), Vec2(0.95, 2.0)}};
  }
  void step() override { run_.step(); }

  void draw(render::Frame& frame) const override {
    frame.caption = fill(tr("Ch 5 walk-through · {0}"), {moment()});
    frame.force_scale = 0.05;
    frame.grounds.push_back({Vec2::Zero(), Vec2::UnitY()});
    frame.bodies.push_back(
        view::body_view(box(), run_.world().shape(box_a), tint(render::palette::sky_blue, 0.35)));
    for (std::size_t i = 0; i < pair().size(); ++i) {
      render::Contact view = view::contact_view(contacts()[i]);
      // n points from box A into the ground: the force on A is λ along −n = N
      view.normal = -view.normal;
      frame.contacts.push_back(view);
      const bool a = corner_name(i) == "a";
      frame.labels.push_back({view.point + Vec2(a ? -0.06 : 0.06, -0.13),
                              corner_name(i) + ": λ = " + fixed(contacts()[i].lambda_normal, 2) + " N",
                              render::palette::ink,
                              a ? render::Label::Align::right : render::Label::Align::left});
    }
    for (double side : {-1.0, 1.0}) inset(frame, side);
    frame.panels.push_back(panel());
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    return view::explain_world_step(run_.world(), run_.report(), {tr("box A"), tr("ground B")});
  }
  void record(tutorial::ViewerStep& step) const override {
    step = view::viewer_step(run_.world(), run_.report(), {tr("box A"), tr("ground B")});
  }

  // normal_force.png: Σ λ over 2 s against m g.
  void write_data(const std::filesystem::path& folder) const override {
    World world = walkthrough_world(StepSettings().beta, solver_);
    const double dt = world.settings().step.dt;
    const double weight = world.bodies()[box_a].mass * -world.settings().step.gravity.y();
    std::vector<std::vector<double>> rows;
    for (int s = 0; s < 120; ++s) {
      WorldReport report;
      world.step(report);
      const Vec6 wrench = report.velocity.constraint_wrench(box_a);
      rows.push_back({s * dt, wrench[1], wrench[5], weight});
    }
    tutorial::write_plot(folder, {"normal_force",
                                  tr("Walk-through: the contact force on box A converges to m g"),
                                  "t − τ (s)",
                                  "f_c1,y (N), τ_c1 (N·m)",
                                  {{tr("f_c1,y = Σ λ_i N_y (eq. 5-9)"), render::palette::blue, false},
                                   {tr("τ_c1 (eq. 5-9)"), render::palette::orange, false},
                                   {"m1 g", render::palette::ink, true}},
                                  rows});
  }

 private:
  const RigidBody& box() const { return run_.bodies_at_t()[box_a]; }
  long step_index() const { return run_.step_index(); }  // steps since τ
  std::vector<Contact> pair() const {
    std::vector<Contact> points;
    for (const ContactPair& p : run_.report().pairs) {
      for (int k = 0; k < p.count; ++k) points.push_back(p.contacts[k]);
    }
    return points;
  }
  std::vector<ContactInfo> contacts() const { return run_.report().contacts(); }

  bool resting() const {
    return step_index() > 2 && box().v.norm() < at_rest &&
           std::abs(box().angular_velocity.z()) < at_rest;
  }

  std::string moment() const {
    switch (step_index()) {
      case 0: return tr("t = τ: one row, the deepest corner a (eq. 5-1..5-11)");
      case 1: return tr("t = τ + Δt: a from the cache, b fresh, J is 2 × 12 (eq. 5-12..5-21)");
      case 2: return tr("t = τ + 2Δt: both corners again (in 3D a third, Fig 5-3)");
      default:
        return resting() ? tr("t → ∞: f_c1 → m1 g, τ_c1 → 0 (each corner about m g / 2)")
                         : tr("settling: both corners kept in the cache");
    }
  }

  // r = R1ᵀ (x − x1) of contact i, the anchor the cache keeps in box A's frame (eq. 5-12).
  Vec3 anchor(std::size_t i) const { return lift(pair().at(i).anchor[0]); }
  // x = x1 + R1 r of contact i: the box's corner at t (eq. 5-12).
  Vec3 corner(std::size_t i) const { return box().x + box().rotation * anchor(i); }
  // "a" for the corner on the −x side of the box (the text's first contact), "b" for the other.
  std::string corner_name(std::size_t i) const { return anchor(i).x() < 0.0 ? "a" : "b"; }
  // The index of the contact at corner `side` (−1: a, +1: b), or −1.
  int contact_at(double side) const {
    for (std::size_t i = 0; i < pair().size(); ++i) {
      if ((corner_name(i) == "a") == (side < 0.0)) return static_cast<int>(i);
    }
    return -1;
  }

  // Corner `side` (−1: a, +1: b) magnified in a square above the box.
  void inset(render::Frame& frame, double side) const {
    const Vec3 r(side * 0.5, -0.5, 0.0);
    const double height = (box().x + box().rotation * r).y();  // the corner's N·x, in m
    ch5::Inset view{Vec2(side * 0.55, 1.62), 0.3, 20.0,
                    std::string(side < 0.0 ? tr("corner a") : tr("corner b")) + " ×20", {}};
    const int i = contact_at(side);
    if (i >= 0) {
      const ContactInfo c = contacts()[static_cast<std::size_t>(i)];
      view.lines[0] = "ε = " + fixed(std::min(c.separation, 0.0), 4) + " m";
      view.lines[1] = c.origin == ContactOrigin::kept      ? tr("kept (eq. 5-12)")
                      : c.origin == ContactOrigin::refound ? tr("re-found: the deepest")
                                                           : tr("new: the deepest");
      ch5::draw_inset(frame, view, box(), r, &c.point);
      return;
    }
    view.lines[0] = height < 0.0 ? "N·x = " + fixed(height, 4) + " m" : tr("no contact");
    view.lines[1] = height < 0.0 ? tr("in, but not the deepest") : "";
    ch5::draw_inset(frame, view, box(), r, nullptr);
  }

  // The text's J row of a contact: box A's block [Nᵀ ((x − x1) × N)ᵀ], then the ground's 0ᵀ 0ᵀ.
  std::string j_row(std::size_t i) const {
    const Vec6 a = run_.report().velocity.mlcp.jacobian(pair().at(i).row, 0);
    std::string text = "[";
    for (int c = 0; c < 6; ++c) text += (c ? " " : "") + entry(a[c]);
    return text + " | 0 0 0 0 0 0]";
  }

  render::Panel panel() const {
    const WorldReport& report = run_.report();
    const double beta = run_.world().settings().step.beta, dt = run_.world().settings().step.dt;
    const Vec6 wrench = report.velocity.constraint_wrench(box_a);
    const int rows = report.velocity.mlcp.row_count();
    const bool at_tau = step_index() == 0;
    render::Panel p;
    p.corner = render::Corner::top_left;
    p.title = fill(tr("step {0} · solver {1}: s = {2}, J is {3} × 12 ({4})"),
                   {std::to_string(step_index()), solver_, counted(rows, tr("row"), tr("rows")),
                    std::to_string(rows), at_tau ? "5-11" : "5-19"});
    p.lines = {"M⁻¹ = diag(m1⁻¹E, I1⁻¹, 0, 0): m1⁻¹ = " + fixed(box().inverse_mass, 1) +
                   ", I1⁻¹ = " + fixed(box().inverse_inertia_world(2, 2), 1) + "  (5-1)",
               "F_ext = [m1 g, 0, 0, 0], m1 g = " +
                   pair_text(box().mass * run_.world().settings().step.gravity, 1) + " N  (5-2)",
               "V: v1 = " + pair_text(box().v, 4) + " m/s, ω1 = " +
                   fixed(box().angular_velocity.z(), 4) + " rad/s  (" + (at_tau ? "5-3" : "3-5") + ")"};
    const std::vector<Contact> points = pair();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Contact& c = points[i];
      const std::string n = corner_name(i);
      const RowTags tags = tags_of(step_index(), n == "b");
      const double epsilon = std::min(c.separation, 0.0);
      // eq. 5-4: v_a = v1 + ω1 × (x_a − x1), the corner's velocity at t
      const Vec3 v = box().v + box().angular_velocity.cross(corner(i) - box().x);
      p.lines.push_back(n + " " + origin_text(c.origin) + ": x_" + n + " = " +
                        pair_text(corner(i), 4) + ", r_" + n + " = " + pair_text(anchor(i), 2) +
                        "  (5-12)");
      p.lines.push_back("  N·v_" + n + " = " + fixed(N.dot(v), 4) + " m/s (5-4, 5-5), ε = " +
                        fixed(epsilon, 5) + " m");
      p.lines.push_back("  ζ = −βε = " + fixed(-beta * epsilon, 5) + " m (" + tags.zeta +
                        "); J V ≥ ζ/Δt = " + fixed(-beta * epsilon / dt, 3) + " m/s (4-5)");
      p.lines.push_back("  J = " + j_row(i) + "  (" + tags.J + ")");
      p.lines.push_back("  λ ∈ [0, ∞) (" + std::string(tags.bounds) + "): λ = " +
                        fixed(report.velocity.solution.lambda[c.row], 4) + " N (" +
                        (at_tau ? "5-9" : "5-21") + ")");
    }
    if (at_tau) {
      p.lines.push_back(fill(tr("  eq. 5-7 read literally (ζ as m/s): λ = {0} N"), {fixed(literal_, 4)}));
    }
    p.lines.push_back("f_c1 = " + pair_text(Vec3(wrench.head<3>()), 4) + " N, τ_c1 = " +
                      fixed(wrench[5], 4) + " N·m  (5-9)");
    p.lines.push_back(tr("text: z up, N = (0, 0, 1); Lamina: y up, N = (0, 1, 0)"));
    return p;
  }

  std::string solver_;  // the method, "text" unless --solver says otherwise
  view::SteppedWorld run_;
  double literal_;  // λ1 at t = τ, eq. 5-7 read literally, in N
};

}  // namespace

int main(int argc, char** argv) {
  tutorial::TutorialInfo info{
      "05_walkthrough",
      "ch5",
      "Chapter 5: the walk-through at t = τ, τ+Δt, τ+2Δt and t → ∞ with the numbers of eq. "
      "5-1..5-21, by the text's own method, and the normal force converging to m g",
      {render::Overlay::contacts, render::Overlay::normals, render::Overlay::forces,
       render::Overlay::centres}};
  for (const SolverInfo& s : solver_list()) info.solvers.push_back(s.name);
  return tutorial::run_tutorial(
      argc, argv, info,
      {[](const tutorial::Options& o) { return std::make_unique<Walkthrough>(o); }});
}
