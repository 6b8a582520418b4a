#include "ch2/spring.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "app/harness/format.h"
#include "app/harness/plot.h"
#include "kinematics/momentum.h"
#include "language/language.h"
#include "motion/integrator.h"

namespace lamina::ch2 {
namespace {

using tutorial::fixed;
using tutorial::json_of;

constexpr double dt = 1.0 / 60.0;         // Δt, in s
constexpr double frequency = 2.0 * M_PI;  // ω = √(k/m), in rad/s: a period of 1 s
constexpr double radius = 0.2;            // the disc, in m
constexpr double density = 1.0;           // kg/m²
constexpr double start_offset = 0.5;      // y(0) − y_rest, in m; v(0) = 0
constexpr double ceiling_height = 2.7;    // the spring's top above the rest point, in m
constexpr double chart_gap = 0.6;         // from the disc's column to the chart, in m
constexpr double chart_speed = 1.5;       // m of chart per s
constexpr double run_length = 3.0;        // s shown by the chart (the default frames)
constexpr double panel_offset = 6.3;      // x distance between the two runs, in m
// Explicit Euler's energy gain per step: E ← E (1 + ω²Δt²) (the test "a spring: …" checks it).
const double growth_per_step = 1.0 + frequency * frequency * dt * dt;

// One run: a disc hung at `rest` on a spring F = −k (x − rest), stepped by one scheme.
struct Run {
  Integration scheme;
  const char* title;           // the panel's title
  const char* rule;            // how x moves
  render::Colour colour;       // of the disc, its chart and its panel's title
  Vec3 rest;                   // the spring's rest point, where the disc hangs still
  RigidBody body;              // after the last step: at t + Δt
  RigidBody at_t;              // at t, where the last step started (what a frame shows)
  std::vector<Vec2> chart;     // (chart position of t, height): the disc's height against time
  double largest_drift = 0.0;  // max |E/E₀ − 1| up to t

  double stiffness() const { return body.mass * frequency * frequency; }  // k = m ω²
  // E = ½ m vᵀv + ½ ωᵀIω (eq. 1-47) plus the spring's ½ k |x − rest|².
  double energy(const RigidBody& b) const {
    return kinetic_energy(b.mass, b.v, b.inertia_world(), b.angular_velocity) +
           0.5 * stiffness() * (b.x - rest).squaredNorm();
  }
  // Where the chart draws height h above the rest point at time t.
  Vec2 chart_point(double t, double h) const {
    return {rest.x() + chart_gap + chart_speed * t, rest.y() + h};
  }
  // Takes the next step: the spring's force at x(t), then eq. 2-3..2-8 by this run's scheme.
  void step(double t) {
    at_t = body;
    body.apply_force_at(-stiffness() * (body.x - rest), body.x);
    integrate(body, dt, scheme);
    body.clear_forces();
    chart.push_back(chart_point(t, at_t.x.y() - rest.y()));
  }
};

Run make_run(Integration scheme, const char* title, const char* rule, render::Colour colour,
             const Vec3& rest) {
  const RigidBody disc = disc_body(density, radius, rest + Vec3(0.0, start_offset, 0.0));
  Run run{scheme, title, rule, colour, rest, disc, disc, {}};
  run.step(0.0);  // step 0: a frame shows the state at t with what its step did from it
  return run;
}

// A coil spring from `top` down to `bottom` (same x), as a zigzag of ten coils.
std::vector<Vec2> spring_path(const Vec2& top, const Vec2& bottom) {
  constexpr int zigs = 20;
  constexpr double lead = 0.12, width = 0.13;
  const double length = top.y() - bottom.y() - 2 * lead;
  std::vector<Vec2> points{top, top - Vec2(0.0, lead)};
  for (int i = 0; i < zigs; ++i) {
    const double side = (i % 2 == 0 ? 1.0 : -1.0) * width;
    points.push_back(top - Vec2(-side, lead + length * (i + 0.5) / zigs));
  }
  points.push_back(bottom + Vec2(0.0, lead));
  points.push_back(bottom);
  return points;
}

class Spring : public tutorial::Scene {
 public:
  Spring()
      : runs_{make_run(Integration::explicit_euler, tr("explicit Euler"), "x(t+Δt) = x + v(t) Δt",
                       render::palette::vermillion, Vec3::Zero()),
              make_run(Integration::semi_implicit, tr("semi-implicit Euler (eq. 2-5)"),
                       "x(t+Δt) = x + v(t+Δt) Δt", render::palette::bluish_green,
                       Vec3(panel_offset, 0.0, 0.0))},
        initial_energy_(runs_[0].energy(runs_[0].at_t)) {
    record_energy();
  }

  tutorial::SceneInfo info() const override {
    const int every = 2;
    const int frames = static_cast<int>(std::lround(run_length / (every * dt))) + 1;
    return {"spring", dt, frames, every, {Vec2(-0.7, -3.3), Vec2(11.6, 2.95)}};
  }

  void step() override {
    ++step_;
    for (Run& run : runs_) run.step(step_ * dt);
    record_energy();
  }

  void draw(render::Frame& frame) const override {
    using namespace render::palette;
    frame.caption =
        tr("Ch 2 · A spring: explicit Euler multiplies E by 1 + ω²Δt² a step, eq. 2-5 keeps it");
    for (const Run& run : runs_) {
      const Vec2 rest = run.rest.head<2>(), x = run.at_t.x.head<2>();
      const Vec2 top = rest + Vec2(0.0, ceiling_height);
      render::Body ceiling;
      ceiling.centre = top + Vec2(0.0, 0.06);
      ceiling.half_extents = {0.3, 0.06};
      ceiling.fill = tint(grey, 0.5);
      ceiling.fixed = true;
      frame.bodies.push_back(ceiling);
      frame.paths.push_back({spring_path(top, x + Vec2(0.0, radius)), ink, false});
      render::Body disc;
      disc.shape = render::Body::Shape::circle;
      disc.centre = x;
      disc.radius = radius;
      disc.fill = tint(run.colour, 0.35);
      disc.velocity = run.at_t.v.head<2>();
      frame.bodies.push_back(disc);
      const Vec2 chart_start = rest + Vec2(chart_gap, 0.0);
      frame.paths.push_back(
          {{chart_start, chart_start + Vec2(chart_speed * run_length, 0.0)}, grid, false});
      frame.paths.push_back({exact_chart(run), grey, true});
      frame.paths.push_back({run.chart, run.colour, false});
      frame.paths.push_back({{x, run.chart.back()}, tint(grey, 0.5), true});
      frame.panels.push_back(run_panel(run));
    }
    for (double side : {1.0, -1.0}) frame.paths.push_back({envelope(side), ink, true});
    frame.legend = {
        {render::LegendEntry::Sample::dashed_line, grey, tr("exact: y₀ cos ωt")},
        {render::LegendEntry::Sample::dashed_line, ink,
         tr("±y₀ (1 + ω²Δt²)^(n/2), from E's growth")},
        {render::LegendEntry::Sample::line, runs_[0].colour, tr("explicit: height against t")},
        {render::LegendEntry::Sample::line, runs_[1].colour,
         tr("semi-implicit: height against t")}};
    frame.legend_corner = render::Corner::top_right;
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e;
    for (const Run& run : runs_) {
      const RigidBody& a = run.at_t;
      const RigidBody& b = run.body;
      e.push_back({run.title,
                   {{"x(t)", "", tr("centre of the disc at t"), json_of(a.x), "m"},
                    {"v(t)", "", tr("velocity at t"), json_of(a.v), "m/s"},
                    {"F", "", tr("spring force −k (x − x_rest)"),
                     json_of(Vec3(-run.stiffness() * (a.x - run.rest))), "N"},
                    {"v(t+Δt)", "2-3", "v + m⁻¹ F Δt", json_of(b.v), "m/s"},
                    {"x(t+Δt)", "2-5", run.rule, json_of(b.x), "m"},
                    {"E/E₀", "1-47", tr("(½ m vᵀv + ½ k |x − x_rest|²) / E(0), at t + Δt"),
                     run.energy(b) / initial_energy_, ""}}});
    }
    return e;
  }

  void write_data(const std::filesystem::path& folder) const override {
    tutorial::write_plot(
        folder, {"spring_energy",
                 tr("Spring, ω = 2π rad/s, Δt = 1/60 s: energy E/E₀ (eq. 1-47 + ½k|x − x_rest|²)"),
                 "t (s)",
                 "E/E₀",
                 {{tr("explicit Euler"), runs_[0].colour, false},
                  {tr("semi-implicit Euler (eq. 2-5)"), runs_[1].colour, false},
                  {"(1 + ω²Δt²)ⁿ, n = t/Δt", render::palette::ink, true}},
                 energy_rows_});
  }

 private:
  void record_energy() {
    std::vector<double> row{step_ * dt};
    for (Run& run : runs_) {
      const double ratio = run.energy(run.at_t) / initial_energy_;
      run.largest_drift = std::max(run.largest_drift, std::abs(ratio - 1.0));
      row.push_back(ratio);
    }
    row.push_back(std::pow(growth_per_step, step_));
    energy_rows_.push_back(row);
  }

  // y_rest + y₀ cos ωt over the chart: what both runs would draw without Δt's error.
  std::vector<Vec2> exact_chart(const Run& run) const {
    std::vector<Vec2> points;
    for (long k = 0; k <= step_; ++k) {
      points.push_back(run.chart_point(k * dt, start_offset * std::cos(frequency * k * dt)));
    }
    return points;
  }

  // Explicit Euler's swing on its chart, y₀ (1 + ω²Δt²)^(n/2) on one side of rest (side ±1):
  // the height where E = ½ k h², as E grows by 1 + ω²Δt² a step.
  std::vector<Vec2> envelope(double side) const {
    std::vector<Vec2> points;
    for (long k = 0; k <= step_; ++k) {
      const double swing = start_offset * std::pow(growth_per_step, 0.5 * k);
      points.push_back(runs_[0].chart_point(k * dt, side * swing));
    }
    return points;
  }

  render::Panel run_panel(const Run& run) const {
    const double ratio = run.energy(run.at_t) / initial_energy_;
    render::Panel panel;
    panel.corner = &run == &runs_[0] ? render::Corner::bottom_left : render::Corner::bottom_right;
    panel.title = run.title;
    panel.title_colour = run.colour;
    panel.lines = {run.rule, "E/E₀ = " + fixed(ratio, 4)};
    if (run.scheme == Integration::explicit_euler) {
      panel.lines.push_back("(1 + ω²Δt²)ⁿ = " + fixed(std::pow(growth_per_step, step_), 4) +
                            ", n = " + std::to_string(step_));
    } else {
      panel.lines.push_back(fill(tr("largest |E/E₀ − 1| = {0}"), {fixed(run.largest_drift, 4)}));
      panel.lines.push_back(fill(tr("bound ωΔt = {0}"), {fixed(frequency * dt, 4)}));
    }
    panel.lines.push_back(
        fill(tr("height − rest = {0} m"), {fixed(run.at_t.x.y() - run.rest.y(), 3)}));
    return panel;
  }

  std::array<Run, 2> runs_;
  double initial_energy_;  // E at t = 0, the same in both runs
  long step_ = 0;
  std::vector<std::vector<double>> energy_rows_;  // t, E/E₀ explicit, semi-implicit, (1+ω²Δt²)ⁿ
};

}  // namespace

tutorial::SceneFactory spring_scene() { return tutorial::scene<Spring>(); }

}  // namespace lamina::ch2
