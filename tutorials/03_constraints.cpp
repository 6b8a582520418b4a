// Chapter 3 — constrained dynamics. Three scenes, each stepped by constrained_step:
//   incline   Fig 3-1: a box held on a line through p with normal N (eq. 3-1..3-4); the constraint
//             force λN cancels the normal part of m g, and the box slides with g sin θ.
//   pendulum  a bob on a rod (distance constraint) twice: β = 0 drifts off the circle |C| grows,
//             β = 0.2 (eq. 3-14) pulls it back; pendulum_drift.png plots |C| against t.
//   chain     four links on revolute joints, pinned to the world, released straight at 1.2 rad;
//   each frame
//             gives PGS's residual ‖W‖ (eq. 3-23, 3-24) from last step's λ and from zero, and
//             pgs_residual.png plots ‖W‖ per sweep for both at one step.
// --explain STEP prints every row of that step: Jmap, Jsp, C, ζ, η, bounds, λ_exp, λ, W, the
// residual per sweep and the dense J, M⁻¹ and J M⁻¹ Jᵀ when small.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "constraints/constrained_step.h"
#include "constraints/dense_system.h"
#include "constraints/distance_constraint.h"
#include "constraints/incline_constraint.h"
#include "constraints/revolute_joint.h"
#include "harness/body_view.h"
#include "harness/format.h"
#include "harness/plot.h"
#include "harness/tutorial.h"

namespace {

using namespace lamina;
using render::palette::blue;
using render::palette::bluish_green;
using render::palette::grey;
using render::palette::ink;
using render::palette::orange;
using render::palette::reddish_purple;
using render::palette::vermillion;
using tutorial::fixed;
using tutorial::Json;
using tutorial::scientific;
using Vec2 = render::Vec2;

const Vec3 gravity(0.0, -9.8, 0.0);  // g, in m/s²

Vec2 planar(const Vec3& v) { return v.head<2>(); }
Vec3 spatial(const Vec2& v) { return Vec3(v.x(), v.y(), 0.0); }

// ---- A constrained system and its last step ----------------------------------------------------

// Bodies, their constraints and what the last constrained_step solved.
struct System {
  std::vector<RigidBody> bodies;
  ConstraintList constraints;
  ConstrainedStepSettings settings;
  WarmStart warm_start;
  StepReport report;      // the last step's; empty before the first
  std::vector<double> C;  // each row's position error at the start of the last step, in m
  bool stepped = false;

  // One step; `errors` are the rows' C now, kept for --explain (the report has ζ, not C).
  void step(std::vector<double> errors) {
    C = std::move(errors);
    constrained_step(bodies, constraints, settings, warm_start, &report);
    stepped = true;
  }
  // F_c = Jᵀ λ on body b from the last step's rows (eq. 3-11), [F τ].
  Vec6 constraint_force(int b) const {
    Vec6 f = Vec6::Zero();
    for (std::size_t i = 0; i < report.mlcp.rows.size(); ++i) {
      const ConstraintRow& row = report.mlcp.rows[i];
      for (int k = 0; k < 2; ++k) {
        if (row.Jmap[k] == b)
          f += row.Jsp[k] * report.solution.lambda[static_cast<Eigen::Index>(i)];
      }
    }
    return f;
  }
  double last_residual() const {
    return report.solution.residuals.empty() ? 0.0 : report.solution.residuals.back();
  }
};

// A fixed block just above a world pin, the ceiling it hangs from.
render::Body mount(const Vec3& pivot) {
  render::Body m;
  m.centre = planar(pivot) + Vec2(0.0, 0.08);
  m.half_extents = {0.25, 0.08};
  m.fill = tint(grey, 0.5);
  m.fixed = true;
  return m;
}

// ---- --explain: the step in the text's terms ---------------------------------------------------

Json json_of(const Eigen::VectorXd& v) {
  Json a = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

Json json_of(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    rows.push_back(json_of(Eigen::VectorXd(m.row(r).transpose())));
  return rows;
}

// JSON has no infinity: an unbounded λ⁻ or λ⁺ is the string "-inf" or "inf".
Json json_of_bound(double bound) {
  if (std::isinf(bound)) return bound < 0 ? "-inf" : "inf";
  return bound;
}

// One section per row: its bodies, J blocks, C (the scene's), ζ, η, d, bounds, λ_exp, λ, W.
void explain_rows(const System& s, const std::vector<std::string>& names,
                  tutorial::Explanation& e) {
  const StepReport& r = s.report;
  for (std::size_t i = 0; i < r.mlcp.rows.size(); ++i) {
    const ConstraintRow& row = r.mlcp.rows[i];
    const auto n = static_cast<Eigen::Index>(i);
    const auto [lo, hi] = row_bounds(row, r.solution.lambda);
    tutorial::Section section{"Row " + std::to_string(i) + ": " + names[i], {}};
    auto& q = section.quantities;
    q.push_back({"Jmap",
                 "",
                 "the row's two bodies (−1: the world), \"Computing Jacobian\"",
                 {row.Jmap[0], row.Jmap[1]},
                 ""});
    q.push_back({"Jsp[0]", "3-7", "J block of body Jmap[0], [v ω]",
                 json_of(Eigen::VectorXd(row.Jsp[0])), ""});
    if (!row.is_one_body()) {
      q.push_back({"Jsp[1]", "3-7", "J block of body Jmap[1], [v ω]",
                   json_of(Eigen::VectorXd(row.Jsp[1])), ""});
    }
    q.push_back({"C", "3-13", "position error ε at the start of the step", s.C[i], "m"});
    q.push_back({"ζ", "3-14, 3-15", "−β C / Δt: asks J V(t+Δt) = ζ", row.zeta, "m/s"});
    q.push_back({"η", "3-16", "ζ/Δt − J (V/Δt + M⁻¹ F_ext)", r.mlcp.eta[n], "m/s²"});
    q.push_back({"d", "3-16", "J_i M⁻¹ J_iᵀ, the diagonal of J B", r.mlcp.d[n], "1/kg"});
    q.push_back({"[λ⁻, λ⁺]",
                 "3-24, 3-25",
                 "bounds of λ (an equality row: unbounded)",
                 {json_of_bound(lo), json_of_bound(hi)},
                 "N"});
    q.push_back({"λ_exp", "", "PGS's starting guess: last step's λ (warm start) or 0",
                 r.lambda_exp[n], "N"});
    q.push_back({"λ", "3-16, 3-24", "the constraint force's size; impulse λ Δt",
                 r.solution.lambda[n], "N"});
    q.push_back({"W", "3-23", "J B λ − η, 0 for a solved equality row", r.W[n], "m/s²"});
    e.push_back(std::move(section));
  }
}

// The bodies after the step, the solver's sweeps and, when small, the dense matrices.
tutorial::Explanation explain_system(const System& s, const std::string& title,
                                     const std::vector<std::string>& row_names) {
  tutorial::Explanation e;
  tutorial::Section bodies{title + ": bodies after the step", {}};
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const RigidBody& body = s.bodies[b];
    const std::string n = s.bodies.size() > 1 ? " " + std::to_string(b) : "";
    bodies.quantities.push_back({"x" + n, "2-5", "centre of mass", tutorial::json_of(body.x), "m"});
    bodies.quantities.push_back({"v" + n, "2-3", "velocity", tutorial::json_of(body.v), "m/s"});
    bodies.quantities.push_back(
        {"ω" + n, "2-4", "angular velocity", tutorial::json_of(body.angular_velocity), "rad/s"});
    if (s.stepped) {
      const Vec6 f = s.constraint_force(static_cast<int>(b));
      bodies.quantities.push_back({"F_c" + n, "3-11", "Jᵀ λ on this body, [F τ] (N, N·m)",
                                   json_of(Eigen::VectorXd(f)), ""});
    }
  }
  e.push_back(std::move(bodies));
  if (!s.stepped) return e;  // step 0: nothing solved yet
  explain_rows(s, row_names, e);
  const StepReport& r = s.report;
  const std::vector<double>& res = r.solution.residuals;
  e.push_back({title + ": projected Gauss-Seidel",
               {{"sweeps", "", "MAX_ITERATION of the text", r.solution.iterations, ""},
                {"‖W‖ per sweep", "3-23, 3-24", "MLCP residual after each sweep",
                 json_of(Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(
                     res.data(), static_cast<Eigen::Index>(res.size())))),
                 "m/s²"}}});
  const int n = static_cast<int>(s.bodies.size());
  const Eigen::MatrixXd J = dense_jacobian(r.mlcp.rows, n);
  const Eigen::MatrixXd Bt = dense_b_transpose(r.mlcp);
  tutorial::Section dense{title + ": the dense system", {}};
  if (n <= 2) {  // 6n ≤ 12 columns: readable in a terminal
    dense.quantities.push_back({"J", "3-8", "s × 6n Jacobian", json_of(J), ""});
    dense.quantities.push_back(
        {"M⁻¹", "3-12", "diag(m⁻¹E, I⁻¹)", json_of(dense_inverse_mass(s.bodies)), ""});
  }
  dense.quantities.push_back({"J M⁻¹ Jᵀ", "3-16", "J B, the matrix PGS sweeps (s × s)",
                              json_of(Eigen::MatrixXd(J * Bt.transpose())), "1/kg"});
  e.push_back(std::move(dense));
  return e;
}

// ---- Scene 1: Fig 3-1, a box on an incline -----------------------------------------------------

constexpr double incline_angle = M_PI / 6.0;  // θ, 30°
const Vec2 box_half(0.4, 0.25);               // box half extents, in m
constexpr double box_density = 5.0;           // kg/m²: m = 2 kg
const Vec2 slope_top(0.0, 3.6);               // a point of the incline's surface, in m
const Vec2 downhill(std::cos(incline_angle), -std::sin(incline_angle));  // unit, along the slope
const Vec2 incline_normal(std::sin(incline_angle), std::cos(incline_angle));  // N
constexpr double incline_force_scale = 0.05;                                  // m of arrow per N

class Incline : public tutorial::Scene {
 public:
  Incline() {
    // The constraint holds the centre of mass on the line through p, half a box above the surface.
    p_ = spatial(slope_top + box_half.y() * incline_normal);
    const Vec3 start = p_ + spatial(1.0 * downhill);
    s_.bodies.push_back(box_body(box_density, box_half.x(), box_half.y(), start, -incline_angle));
    s_.constraints.push_back(std::make_unique<InclineConstraint>(0, p_, spatial(incline_normal)));
  }

  tutorial::SceneInfo info() const override {
    return {"incline", 1.0 / 60.0, 46, 2, {Vec2(-0.6, -0.8), Vec2(8.6, 4.4)}};
  }

  void step() override {
    previous_speed_ = speed();
    s_.step({error()});
  }

  void draw(render::Frame& frame) const override {
    const RigidBody& box = s_.bodies[0];
    frame.caption = "Ch 3 · Fig 3-1: a box held on an incline, (x − p)·N = 0 (eq. 3-1..3-4)";
    frame.force_scale = incline_force_scale;
    frame.velocity_scale = 0.15;
    frame.grounds.push_back({slope_top, incline_normal});
    // θ between the slope and the horizontal, where the surface meets y = 0
    const double foot = slope_top.y() / std::tan(incline_angle);
    frame.paths.push_back({{Vec2(foot - 1.6, 0.0), Vec2(foot + 1.8, 0.0)}, grey, true});
    frame.labels.push_back({Vec2(foot + 1.0, 0.12), "θ = 30°", ink, render::Label::Align::centre});
    // p and N, drawn on the line the constraint holds the centre on
    const Vec2 p = planar(p_);
    frame.paths.push_back({{p - 0.5 * downhill, p + 7.2 * downhill}, grey, true});
    frame.arrows.push_back({p, p + 0.6 * incline_normal, ink, "N", std::nullopt});
    frame.labels.push_back({p - Vec2(0.12, 0.05), "p", ink, render::Label::Align::right});
    frame.bodies.push_back(
        tutorial::box_view(box, box_half, tint(render::palette::sky_blue, 0.35)));
    const Vec2 x = planar(box.x);
    const Vec2 weight = planar(box.mass * gravity),
               support = planar(lambda() * spatial(incline_normal));
    const double k = incline_force_scale;
    frame.arrows.push_back({x, x + k * weight, vermillion, "m g", render::Overlay::forces});
    if (s_.stepped) {
      frame.arrows.push_back({x, x + k * support, blue, "λN", render::Overlay::forces});
      frame.arrows.push_back(
          {x, x + k * (weight + support), bluish_green, "", render::Overlay::forces});
    }
    frame.panels.push_back(panel());
    frame.legend = {
        {render::LegendEntry::Sample::arrow, vermillion, "weight m g"},
        {render::LegendEntry::Sample::arrow, blue, "constraint force F_c = Jᵀλ = λN (3-11)"},
        {render::LegendEntry::Sample::arrow, bluish_green, "m g + λN = m g sin θ down the slope"},
        {render::LegendEntry::Sample::dashed_line, grey, "C = (x − p)·N = 0"}};
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    return explain_system(s_, "Fig 3-1 incline", {"incline, C = (x − p)·N (eq. 3-1)"});
  }

 private:
  double lambda() const { return s_.stepped ? s_.report.solution.lambda[0] : 0.0; }
  double error() const { return (s_.bodies[0].x - p_).dot(spatial(incline_normal)); }
  double speed() const { return planar(s_.bodies[0].v).dot(downhill); }

  render::Panel panel() const {
    const RigidBody& box = s_.bodies[0];
    const double g = gravity.norm(), dt = s_.settings.dt;
    render::Panel panel;
    panel.corner = render::Corner::top_right;
    panel.title = "The incline in numbers";
    panel.lines = {"m = " + fixed(box.mass, 1) + " kg   θ = 30°   N = (" +
                       fixed(incline_normal.x()) + ", " + fixed(incline_normal.y()) + ")",
                   "C = (x − p)·N     = " + scientific(error()) + " m  (3-1)"};
    if (!s_.stepped) {
      panel.lines.push_back("released at rest; step 1 solves λ");
      return panel;
    }
    const StepReport& r = s_.report;
    panel.lines.insert(
        panel.lines.end(),
        {"J = [Nᵀ 0ᵀ]   J M⁻¹ Jᵀ = 1/m = " + fixed(r.mlcp.d[0]) + " 1/kg",
         "ζ = −βC/Δt       = " + fixed(r.mlcp.rows[0].zeta) + " m/s  (3-14)",
         "η = ζ/Δt − J(V/Δt + M⁻¹F) = " + fixed(r.mlcp.eta[0]) + " m/s²  (3-16)",
         "λ = η / (J M⁻¹ Jᵀ) = " + fixed(lambda()) + " N  (3-3, 3-4)",
         "m g cos θ        = " + fixed(box.mass * g * std::cos(incline_angle)) + " N  (theory)",
         "a along slope    = " + fixed((speed() - previous_speed_) / dt) + " m/s²",
         "g sin θ          = " + fixed(g * std::sin(incline_angle)) + " m/s²  (theory)",
         "arrows: " + fixed(incline_force_scale, 2) + " m per N"});
    return panel;
  }

  System s_;
  Vec3 p_;                     // p, a point of the line the centre is held on, in m
  double previous_speed_ = 0;  // v·(down the slope) before the last step, in m/s
};

// ---- Scene 2: a pendulum on a rod, with and without the bias β ---------------------------------

constexpr double rod_length = 1.5;             // L, in m
constexpr double bob_radius = 0.15;            // in m
constexpr double release_angle = 1.0;          // θ0 from hanging, in rad
constexpr double pendulum_dt = 1.0 / 30.0;     // Δt, in s (large on purpose: the drift shows)
constexpr double pendulum_force_scale = 0.05;  // m of arrow per N

struct Pendulum {
  const char* title;
  double beta;  // β of eq. 3-14
  render::Colour colour;
  Vec3 pivot;  // the rod's world end, in m
  System s;
  std::vector<Vec2> trail;

  Pendulum(const char* title_, double beta_, render::Colour colour_, const Vec3& pivot_)
      : title(title_), beta(beta_), colour(colour_), pivot(pivot_) {
    const Vec3 bob =
        pivot + rod_length * Vec3(std::sin(release_angle), -std::cos(release_angle), 0);
    const double density = 1.0 / (M_PI * bob_radius * bob_radius);  // m = 1 kg
    s.bodies.push_back(disc_body(density, bob_radius, bob));
    s.constraints.push_back(std::make_unique<DistanceConstraint>(
        Anchor{world, pivot}, Anchor{0, Vec3::Zero()}, rod_length));
    s.settings.dt = pendulum_dt;
    s.settings.beta = beta;
    trail.push_back(planar(bob));
  }
  double error() const { return (s.bodies[0].x - pivot).norm() - rod_length; }  // C = |d| − L
};

class PendulumPair : public tutorial::Scene {
 public:
  PendulumPair()
      : runs_{Pendulum("β = 0: no bias", 0.0, vermillion, Vec3(-2.7, 0.6, 0.0)),
              Pendulum("β = 0.2 (eq. 3-14)", 0.2, bluish_green, Vec3(2.7, 0.6, 0.0))} {
    record();
  }

  tutorial::SceneInfo info() const override {
    return {"pendulum", pendulum_dt, 91, 2, {Vec2(-5.4, -2.6), Vec2(5.4, 3.0)}};
  }

  void step() override {
    for (Pendulum& run : runs_) {
      run.s.step({run.error()});
      run.trail.push_back(planar(run.s.bodies[0].x));
    }
    ++step_;
    record();
  }

  void draw(render::Frame& frame) const override {
    frame.caption =
        "Ch 3 · A pendulum on a rod: C = |p − pivot| − L drifts unless β > 0 (eq. 3-14)";
    frame.force_scale = pendulum_force_scale;
    for (const Pendulum& run : runs_) {
      const RigidBody& bob = run.s.bodies[0];
      frame.paths.push_back({circle_arc(run.pivot), grey, true});
      frame.paths.push_back({run.trail, tint(run.colour, 0.6), false});
      frame.bodies.push_back(mount(run.pivot));
      frame.joints.push_back({planar(run.pivot), planar(bob.x)});
      render::Body view;
      view.shape = render::Body::Shape::circle;
      view.centre = planar(bob.x);
      view.angle = planar_angle(bob.q);
      view.radius = bob_radius;
      view.fill = tint(run.colour, 0.45);
      view.velocity = planar(bob.v);
      frame.bodies.push_back(view);
      if (run.s.stepped) {
        const Vec2 force = run.s.constraint_force(0).head<2>();
        frame.arrows.push_back({planar(bob.x), planar(bob.x) + pendulum_force_scale * force, blue,
                                "Jᵀλ", render::Overlay::forces});
      }
      frame.panels.push_back(panel(run));
    }
    frame.legend = {
        {render::LegendEntry::Sample::dashed_line, grey, "C = 0: the circle |p − pivot| = L"},
        {render::LegendEntry::Sample::arrow, blue, "rod force F_c = Jᵀλ (3-11)"}};
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e;
    for (const Pendulum& run : runs_) {
      tutorial::Explanation one = explain_system(run.s, std::string("Pendulum, ") + run.title,
                                                 {"rod, C = |p_b − p_a| − L"});
      e.insert(e.end(), one.begin(), one.end());
    }
    return e;
  }

  void write_data(const std::filesystem::path& folder) const override {
    tutorial::write_plot(
        folder,
        {"pendulum_drift",
         "Pendulum on a rod, L = 1.5 m, Δt = 1/30 s: drift |C| = ||p − pivot| − L|",
         "t (s)",
         "|C| (m)",
         {{runs_[0].title, runs_[0].colour, false}, {runs_[1].title, runs_[1].colour, false}},
         drift_rows_});
  }

 private:
  void record() {
    drift_rows_.push_back(
        {step_ * pendulum_dt, std::abs(runs_[0].error()), std::abs(runs_[1].error())});
  }

  static std::vector<Vec2> circle_arc(const Vec3& pivot) {
    std::vector<Vec2> points;
    for (int i = -40; i <= 40; ++i) {
      const double a = 1.3 * i / 40.0;
      points.push_back(planar(pivot) + rod_length * Vec2(std::sin(a), -std::cos(a)));
    }
    return points;
  }

  render::Panel panel(const Pendulum& run) const {
    render::Panel panel;
    panel.corner = &run == &runs_[0] ? render::Corner::top_left : render::Corner::top_right;
    panel.title = std::string("Pendulum, ") + run.title;
    panel.title_colour = run.colour;
    panel.lines = {"L = 1.5 m   m = 1 kg   θ0 = 1 rad",
                   "C = |p − pivot| − L = " + fixed(run.error(), 4) + " m"};
    if (run.s.stepped) {
      const StepReport& r = run.s.report;
      panel.lines.push_back("ζ = −βC/Δt = " + fixed(r.mlcp.rows[0].zeta, 4) + " m/s  (3-14)");
      panel.lines.push_back("λ = " + fixed(r.solution.lambda[0], 2) + " N (rod tension −λ)");
    }
    return panel;
  }

  std::array<Pendulum, 2> runs_;
  long step_ = 0;
  std::vector<std::vector<double>> drift_rows_;  // t, |C| with β = 0, |C| with β = 0.2
};

// ---- Scene 3: a chain on revolute joints, and PGS with and without warm start ------------------

constexpr int links = 4;
const Vec2 link_half(0.25, 0.05);       // half extents of a link, in m
constexpr double link_density = 20.0;   // kg/m²: 1 kg per link
const Vec3 chain_pivot(0.0, 0.0, 0.0);  // the world pin, in m
constexpr double chain_release = 1.2;   // the straight chain's angle from hanging, in rad
const Vec3 chain_direction(std::sin(chain_release), -std::cos(chain_release), 0.0);  // unit
constexpr int comparison_step = 30;    // the step pgs_residual.png shows
constexpr int comparison_sweeps = 30;  // sweeps plotted

using Pins = std::vector<std::pair<Anchor, Anchor>>;  // each joint's two anchors, in order

// The links laid out straight from chain_pivot, chain_release from hanging.
std::vector<RigidBody> level_links() {
  std::vector<RigidBody> bodies;
  for (int i = 0; i < links; ++i) {
    const Vec3 centre = chain_pivot + (2 * i + 1) * link_half.x() * chain_direction;
    bodies.push_back(
        box_body(link_density, link_half.x(), link_half.y(), centre, chain_release - M_PI / 2.0));
  }
  return bodies;
}

// Joint i pins link i−1 (the world for i = 0) to link i at their shared end.
Pins chain_pins(const std::vector<RigidBody>& level) {
  Pins pins;
  for (int i = 0; i < links; ++i) {
    const Vec3 pin = chain_pivot + 2 * i * link_half.x() * chain_direction;
    pins.emplace_back(anchor_at(level, i - 1, pin), anchor_at(level, i, pin));
  }
  return pins;
}

// C of each joint row, x then y: the components of p_b − p_a.
std::vector<double> joint_errors(const std::vector<RigidBody>& bodies, const Pins& pins) {
  std::vector<double> C;
  for (const auto& [a, b] : pins) {
    const Vec3 gap = anchor_position(bodies, b) - anchor_position(bodies, a);
    C.push_back(gap.x());
    C.push_back(gap.y());
  }
  return C;
}

System make_chain() {
  System s;
  s.bodies = level_links();
  for (const auto& [a, b] : chain_pins(s.bodies)) {
    s.constraints.push_back(std::make_unique<RevoluteJoint>(a, b));
  }
  return s;
}

// The same step taken twice from the same state: from last step's λ and from λ = 0.
struct Comparison {
  StepReport warm, cold;
};

Comparison compare_warm_and_cold(const System& s, int sweeps) {
  Comparison c;
  for (bool warm : {true, false}) {
    std::vector<RigidBody> bodies = s.bodies;
    WarmStart start = s.warm_start;
    ConstrainedStepSettings settings = s.settings;
    settings.warm_start = warm;
    settings.pgs.iterations = sweeps;
    constrained_step(bodies, s.constraints, settings, start, warm ? &c.warm : &c.cold);
  }
  return c;
}

class Chain : public tutorial::Scene {
 public:
  Chain() : s_(make_chain()), pins_(chain_pins(level_links())), trail_{tip()} {}

  tutorial::SceneInfo info() const override {
    return {"chain", 1.0 / 60.0, 91, 2, {Vec2(-3.3, -2.3), Vec2(3.3, 1.1)}};
  }

  void step() override {
    cold_residual_ =
        compare_warm_and_cold(s_, s_.settings.pgs.iterations).cold.solution.residuals.back();
    s_.step(joint_errors(s_.bodies, pins_));
    trail_.push_back(tip());
  }

  void draw(render::Frame& frame) const override {
    frame.caption = "Ch 3 · A chain on revolute joints: J B λ = η solved by PGS (eq. 3-16, 3-24)";
    frame.paths.push_back({trail_, tint(bluish_green, 0.6), false});
    frame.bodies.push_back(mount(chain_pivot));
    const render::Colour fills[] = {render::palette::sky_blue, orange, reddish_purple,
                                    bluish_green};
    for (int i = 0; i < links; ++i) {
      frame.bodies.push_back(tutorial::box_view(s_.bodies[static_cast<std::size_t>(i)], link_half,
                                                tint(fills[i], 0.45)));
    }
    for (const auto& [a, b] : pins_) {
      frame.joints.push_back(
          {planar(anchor_position(s_.bodies, a)), planar(anchor_position(s_.bodies, b))});
    }
    frame.panels.push_back(panel());
    frame.legend = {{render::LegendEntry::Sample::line, tint(bluish_green, 0.6),
                     "path of the chain's free end"}};
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    std::vector<std::string> names;
    for (int i = 0; i < links; ++i) {
      const std::string joint =
          i == 0 ? "world pin – link 0"
                 : "link " + std::to_string(i - 1) + " – link " + std::to_string(i);
      names.push_back(joint + ", x row: C = x̂·(p_b − p_a)");
      names.push_back(joint + ", y row: C = ŷ·(p_b − p_a)");
    }
    return explain_system(s_, "Chain", names);
  }

  // pgs_residual.png: a fresh chain to comparison_step, then that step from both guesses.
  void write_data(const std::filesystem::path& folder) const override {
    System s = make_chain();
    const Pins pins = chain_pins(level_links());
    for (int i = 1; i < comparison_step; ++i) s.step(joint_errors(s.bodies, pins));
    const Comparison c = compare_warm_and_cold(s, comparison_sweeps);
    std::vector<std::vector<double>> rows;
    for (int k = 0; k < comparison_sweeps; ++k) {
      const auto i = static_cast<std::size_t>(k);
      rows.push_back({k + 1.0, c.warm.solution.residuals[i], c.cold.solution.residuals[i]});
    }
    tutorial::write_plot(
        folder, {"pgs_residual",
                 "Chain of 4 links, step 30 (t = 0.5 s): PGS residual per sweep (eq. 3-23, 3-24)",
                 "sweep",
                 "‖W‖ (m/s²), log scale",
                 {{"from last step's λ (warm start)", bluish_green, false},
                  {"from λ = 0", vermillion, false}},
                 rows,
                 "top right",
                 true});
  }

 private:
  // The free end of the last link.
  Vec2 tip() const {
    const RigidBody& last = s_.bodies.back();
    return planar(last.x + last.rotation * Vec3(link_half.x(), 0.0, 0.0));
  }

  render::Panel panel() const {
    double worst_gap = 0.0;
    const std::vector<double> C = joint_errors(s_.bodies, pins_);
    for (std::size_t k = 0; k < C.size(); k += 2)
      worst_gap = std::max(worst_gap, std::hypot(C[k], C[k + 1]));
    render::Panel panel;
    panel.corner = render::Corner::top_left;
    panel.title = "PGS on the chain (4 joints, 8 rows)";
    panel.lines = {"J: 8 × 24 (3-8)   J B: 8 × 8 (3-16)",
                   "widest joint gap |p_b − p_a| = " + fixed(worst_gap, 4) + " m"};
    if (s_.stepped) {
      const int sweeps = s_.report.solution.iterations;
      panel.lines.push_back("‖W‖ after " + std::to_string(sweeps) + " sweeps (3-23, 3-24):");
      panel.lines.push_back("  from last step's λ  " + scientific(s_.last_residual()) + " m/s²");
      panel.lines.push_back("  from λ = 0          " + scientific(cold_residual_) + " m/s²");
    }
    return panel;
  }

  System s_;
  Pins pins_;                   // each joint's anchors, the world pin first
  std::vector<Vec2> trail_;     // the free end's positions, one per step, in m
  double cold_residual_ = 0.0;  // ‖W‖ of the last step had PGS started from λ = 0, in m/s²
};

}  // namespace

int main(int argc, char** argv) {
  const tutorial::TutorialInfo info{
      "03_constraints",
      "ch3",
      "Chapter 3: Fig 3-1's incline, a pendulum's drift and a chain, with PGS's residual plot",
      {render::Overlay::forces, render::Overlay::centres}};
  return tutorial::run_tutorial(
      argc, argv, info,
      {tutorial::scene<Incline>(), tutorial::scene<PendulumPair>(), tutorial::scene<Chain>()});
}
