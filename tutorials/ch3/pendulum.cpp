#include "ch3/pendulum.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "app/harness/plot.h"
#include "app/views/constraints/constraint_view.h"
#include "ch3/constrained_system.h"
#include "constraints/distance_constraint.h"
#include "language/language.h"

namespace lamina::ch3 {
namespace {

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
    s.settings.step.dt = pendulum_dt;
    s.settings.step.beta = beta;
    advance();
  }
  // C = |d| − L of the bob at a state
  double error(const RigidBody& bob) const { return (bob.x - pivot).norm() - rod_length; }
  // Takes the next step; the trail gains the bob's position at its t.
  void advance() {
    s.step({error(s.bodies[0])});
    trail.push_back(planar(s.at_t[0].x));
  }
};

class PendulumPair : public tutorial::Scene {
 public:
  PendulumPair()
      : runs_{Pendulum(tr("β = 0: no bias"), 0.0, vermillion, Vec3(-2.7, 0.6, 0.0)),
              Pendulum(tr("β = 0.2 (eq. 3-14)"), 0.2, bluish_green, Vec3(2.7, 0.6, 0.0))} {
    record();
  }

  tutorial::SceneInfo info() const override {
    return {"pendulum", pendulum_dt, 91, 2, {Vec2(-5.4, -2.6), Vec2(5.4, 3.0)}};
  }

  void step() override {
    for (Pendulum& run : runs_) run.advance();
    record();
  }

  void draw(render::Frame& frame) const override {
    frame.caption =
        tr("Ch 3 · A pendulum on a rod: C = |p − pivot| − L drifts unless β > 0 (eq. 3-14)");
    frame.force_scale = pendulum_force_scale;
    for (const Pendulum& run : runs_) {
      const RigidBody& bob = run.s.at_t[0];
      frame.paths.push_back({circle_arc(run.pivot), grey, true});
      frame.paths.push_back({run.trail, tint(run.colour, 0.6), false});
      frame.bodies.push_back(mount(run.pivot));
      frame.joints.push_back(*view::joint_view(run.s.at_t, *run.s.constraints[0]));
      render::Body view;
      view.shape = render::Body::Shape::circle;
      view.centre = planar(bob.x);
      view.angle = planar_angle(bob.q);
      view.radius = bob_radius;
      view.fill = tint(run.colour, 0.45);
      view.velocity = planar(bob.v);
      frame.bodies.push_back(view);
      const Vec2 force = run.s.report.constraint_wrench(0).head<2>();
      frame.arrows.push_back({planar(bob.x), planar(bob.x) + pendulum_force_scale * force, blue,
                              "Jᵀλ", render::Overlay::forces});
      frame.panels.push_back(panel(run));
    }
    frame.legend = {
        {render::LegendEntry::Sample::dashed_line, grey, tr("C = 0: the circle |p − pivot| = L")},
        {render::LegendEntry::Sample::arrow, blue, tr("rod force F_c = Jᵀλ (3-11)")}};
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e;
    for (const Pendulum& run : runs_) {
      tutorial::Explanation one = explain_system(run.s, fill(tr("Pendulum, {0}"), {run.title}),
                                                 {tr("rod, C = |p_b − p_a| − L")});
      e.insert(e.end(), one.begin(), one.end());
    }
    return e;
  }

  void write_data(const std::filesystem::path& folder) const override {
    tutorial::write_plot(
        folder,
        {"pendulum_drift",
         tr("Pendulum on a rod, L = 1.5 m, Δt = 1/30 s: drift |C| = ||p − pivot| − L|"),
         "t (s)",
         "|C| (m)",
         {{runs_[0].title, runs_[0].colour, false}, {runs_[1].title, runs_[1].colour, false}},
         drift_rows_});
  }

 private:
  void record() {
    const auto drift = [](const Pendulum& run) { return std::abs(run.error(run.s.at_t[0])); };
    drift_rows_.push_back({runs_[0].s.step_index * pendulum_dt, drift(runs_[0]), drift(runs_[1])});
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
    panel.title = fill(tr("Pendulum, {0}"), {run.title});
    panel.title_colour = run.colour;
    panel.lines = {"L = 1.5 m   m = 1 kg   θ0 = 1 rad",
                   fill(tr("C = |p − pivot| − L = {0} m"), {fixed(run.error(run.s.at_t[0]), 4)})};
    const StepReport& r = run.s.report;
    panel.lines.push_back("ζ = −βC/Δt = " + fixed(r.mlcp.zeta(0), 4) + " m/s  (3-14)");
    panel.lines.push_back(fill(tr("λ = {0} N (rod tension −λ)"), {fixed(r.solution.lambda[0], 2)}));
    return panel;
  }

  std::array<Pendulum, 2> runs_;
  std::vector<std::vector<double>> drift_rows_;  // t, |C| with β = 0, |C| with β = 0.2
};

}  // namespace

tutorial::SceneFactory pendulum_scene() { return tutorial::scene<PendulumPair>(); }

}  // namespace lamina::ch3
