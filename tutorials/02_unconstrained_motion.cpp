// Chapter 2 — unconstrained motion. Three scenes:
//   forces_at_points  Fig 2-1: three forces at points of a body add up to F and τ (eq. 1-31..1-33),
//                     which move it (ch2/forces_at_points.h).
//   thrown_box        the same spinning box thrown twice, side by side: on the left the explicit
//                     variant (x moves with v(t)), on the right the text's semi-implicit step
//                     (eq. 2-5: x moves with v(t+Δt)). Under a constant force both are first
//                     order and neither is the more stable: both leave the exact parabola by
//                     ½ g Δt t, in opposite directions, and the total energy drifts by
//                     ±½ m g² Δt t; the plot energy.png shows it.
//   spring            where the text's "implicit is more stable" shows: on a spring explicit
//                     Euler's energy grows by 1 + ω²Δt² a step, eq. 2-5's stays bounded; the plot
//                     spring_energy.png (ch2/spring.h).
#include <array>

#include "app/views/motion/body_view.h"
#include "app/harness/format.h"
#include "app/harness/plot.h"
#include "app/harness/tutorial.h"
#include "ch2/forces_at_points.h"
#include "ch2/spring.h"
#include "kinematics/momentum.h"
#include "language/language.h"
#include "motion/integrator.h"

namespace {

using namespace lamina;
using tutorial::fixed;

constexpr double dt = 1.0 / 30.0;            // Δt, in s (large on purpose: the drift shows)
const Vec3 gravity(0.0, -9.8, 0.0);          // g, in m/s²
const Vec2 half_extents(0.4, 0.25);  // box half extents, in m
constexpr double density = 1.0;              // kg/m²
const Vec3 launch(0.6, 0.6, 0.0);            // x(0) in each panel, in m
const Vec3 throw_velocity(3.0, 6.5, 0.0);    // v(0), in m/s
constexpr double throw_spin = 5.0;           // ω(0) about z, in rad/s
constexpr double panel_offset = 7.0;         // x distance between the two panels, in m

// One of the two runs: an integration scheme, its body and what it has done so far.
struct Run {
  Integration scheme;
  const char* title;
  const char* rule;  // how x moves, as the panel states it
  render::Colour colour;
  Vec3 origin;  // where this panel's throw starts
  std::vector<RigidBody> bodies;  // after step k: at t + Δt
  std::vector<RigidBody> at_t;    // the bodies at t, where step k started (what a frame shows)
  std::vector<Vec2> trail;        // the centre's path up to t

  // Takes step k + 1 (eq. 2-1..2-8 with F = m g); the trail gains the centre at its t.
  void step() {
    at_t = bodies;
    step_unconstrained(bodies, gravity, dt, scheme);
    trail.push_back(at_t[0].x.head<2>());
  }
};

double total_energy(const RigidBody& b) {
  // eq. 1-47 plus the potential energy −m g·x (the text's E is kinetic only).
  return kinetic_energy(b.mass, b.v, b.inertia_world(), b.angular_velocity) -
         b.mass * gravity.dot(b.x);
}

// x(0) + v(0) t + ½ g t², where the exact solution is at time t.
Vec3 exact_position(const Vec3& origin, double t) {
  return origin + throw_velocity * t + 0.5 * gravity * t * t;
}

Run make_run(Integration scheme, const char* title, const char* rule, render::Colour colour,
             const Vec3& origin) {
  RigidBody box = box_body(density, half_extents.x(), half_extents.y(), origin);
  box.v = throw_velocity;
  box.angular_velocity = Vec3(0.0, 0.0, throw_spin);
  Run run{scheme, title, rule, colour, origin, {box}, {}, {}};
  run.step();  // step 0: a frame shows the state at t with what its step did from it
  return run;
}

class ThrownBox : public tutorial::Scene {
 public:
  ThrownBox()
      : runs_{make_run(Integration::explicit_euler, tr("explicit Euler"), "x(t+Δt) = x + v(t) Δt",
                       render::palette::vermillion, launch),
              make_run(Integration::semi_implicit, tr("semi-implicit Euler (eq. 2-5)"),
                       "x(t+Δt) = x + v(t+Δt) Δt", render::palette::bluish_green,
                       launch + Vec3(panel_offset, 0.0, 0.0))},
        initial_energy_(total_energy(runs_[0].at_t[0])) {
    record_energy();
  }

  tutorial::SceneInfo info() const override {
    return {"thrown_box", dt, 41, 1, {Vec2(-0.3, -1.6), Vec2(13.0, 5.4)}};
  }

  void step() override {
    ++step_;
    for (Run& run : runs_) run.step();
    record_energy();
  }

  void draw(render::Frame& frame) const override {
    frame.caption =
        tr("Ch 2 · A thrown spinning box, eq. 2-3..2-8: explicit vs semi-implicit Euler");
    frame.velocity_scale = 0.12;
    const double t = step_ * dt;
    for (const Run& run : runs_) {
      frame.paths.push_back({exact_path(run.origin), render::palette::grey, true});
      frame.paths.push_back({run.trail, run.colour, false});
      frame.bodies.push_back(
          view::box_view(run.at_t[0], half_extents, tint(run.colour, 0.35)));
      frame.panels.push_back(run_panel(run, t));
    }
    const double divider = launch.x() + panel_offset - 1.3;
    frame.paths.push_back(
        {{Vec2(divider, -1.6), Vec2(divider, 3.6)}, render::palette::grid, false});
    frame.legend = {
        {render::LegendEntry::Sample::dashed_line, render::palette::grey,
         tr("exact: x₀ + v₀t + ½gt²")},
        {render::LegendEntry::Sample::line, runs_[0].colour, tr("explicit Euler: centre's path")},
        {render::LegendEntry::Sample::line, runs_[1].colour, tr("semi-implicit: centre's path")}};
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e;
    for (const Run& run : runs_) e.push_back(explain_run(run));
    return e;
  }

  void write_data(const std::filesystem::path& folder) const override {
    tutorial::write_plot(
        folder,
        {"energy",
         tr("Thrown box: total energy E = ½mvᵀv + ½ωᵀIω + mgy (eq. 1-47 + potential), Δt = 1/30 s"),
         "t (s)",
         "E (J)",
         {{tr("explicit Euler"), runs_[0].colour, false},
          {tr("semi-implicit Euler (eq. 2-5)"), runs_[1].colour, false},
          {tr("exact (constant)"), render::palette::ink, true}},
         energy_rows_});
  }

 private:
  void record_energy() {
    energy_rows_.push_back({step_ * dt, total_energy(runs_[0].at_t[0]),
                            total_energy(runs_[1].at_t[0]), initial_energy_});
  }

  std::vector<Vec2> exact_path(const Vec3& origin) const {
    std::vector<Vec2> points;
    const int last = info().frames - 1;
    for (int i = 0; i <= last; ++i) points.push_back(exact_position(origin, i * dt).head<2>());
    return points;
  }

  render::Panel run_panel(const Run& run, double t) const {
    const RigidBody& b = run.at_t[0];
    const double drift = total_energy(b) - initial_energy_;
    // Under constant g each step changes E by ±½ m g² Δt², so E drifts by ±½ m g² Δt t.
    const double predicted = 0.5 * b.mass * gravity.squaredNorm() * dt * t;
    render::Panel panel;
    panel.corner = &run == &runs_[0] ? render::Corner::top_left : render::Corner::top_right;
    panel.title = run.title;
    panel.title_colour = run.colour;
    panel.lines = {
        run.rule,
        "v = " + fixed(b.v, 2) + " m/s",
        "E = " + fixed(total_energy(b), 3) + " J",
        "E − E₀ = " + fixed(drift, 3) + " J",
        fill(tr("½mg²Δt·t = {0} J (theory)"), {fixed(predicted, 3)}),
        "|x − x_exact| = " + fixed((b.x - exact_position(run.origin, t)).norm(), 3) + " m"};
    return panel;
  }

  // Step k: the state at t, then each of eq. 2-3..2-8 at t + Δt.
  tutorial::Section explain_run(const Run& run) const {
    const RigidBody& a = run.at_t[0];
    const RigidBody& b = run.bodies[0];
    using tutorial::json_of;
    return {
        run.title,
        {{"x(t)", "", tr("centre of mass at t"), json_of(a.x), "m"},
         {"v(t)", "", tr("velocity at t"), json_of(a.v), "m/s"},
         {"ω(t)", "", tr("angular velocity at t"), json_of(a.angular_velocity), "rad/s"},
         {"F", "5-2", tr("external force m g, the only force"), json_of(Vec3(b.mass * gravity)),
          "N"},
         {"v(t+Δt)", "2-3", "v + m⁻¹ F Δt", json_of(b.v), "m/s"},
         {"ω(t+Δt)", "2-4", "ω + I⁻¹ τ Δt (τ = 0)", json_of(b.angular_velocity), "rad/s"},
         {"x(t+Δt)", "2-5", run.rule, json_of(b.x), "m"},
         {"q(t+Δt)", "2-6", tr("q + ½ ω̂ q Δt, renormalised"), json_of(b.q), ""},
         {"R", "2-7", tr("rotation matrix of q (eq. 1-22)"), json_of(b.rotation), ""},
         {"I(t+Δt)", "2-8", "R I(0) Rᵀ", json_of(b.inertia_world()), "kg·m²"},
         {"E", "1-47", tr("kinetic energy + potential −m g·x"), total_energy(b), "J"}}};
  }

  std::array<Run, 2> runs_;
  double initial_energy_;  // E at t = 0
  long step_ = 0;
  std::vector<std::vector<double>> energy_rows_;  // t, E explicit, E semi-implicit, E exact
};

}  // namespace

int main(int argc, char** argv) {
  const tutorial::TutorialInfo info{
      "02_unconstrained_motion",
      "ch2",
      "Chapter 2: forces at points (Fig 2-1), and explicit vs semi-implicit Euler on a thrown "
      "box and on a spring, with their energy plots",
      {render::Overlay::velocities, render::Overlay::centres}};
  return tutorial::run_tutorial(
      argc, argv, info,
      {ch2::forces_at_points_scene(), tutorial::scene<ThrownBox>(), ch2::spring_scene()});
}
