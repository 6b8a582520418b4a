#include "ch1/turning_particle.h"

#include <array>
#include <cmath>

#include "app/harness/format.h"
#include "app/harness/sketch3d.h"
#include "kinematics/particle.h"
#include "kinematics/rotation.h"
#include "language/language.h"

namespace lamina::ch1 {
namespace {

using tutorial::arc;
using tutorial::draw_world_axes;
using tutorial::fixed;
using tutorial::json_of;

constexpr double frame_dt = 1.0 / 30.0;     // time between frames, in s
const Vec3 axis = Vec3::UnitY();            // the rotation axis ω/|ω|
constexpr double spin = M_PI / 2;           // |ω|, in rad/s: one turn in 4 s
const Vec3 omega = spin * axis;             // ω
const Vec3 half_extents(0.9, 0.5, 0.6);     // the body, a box about its centre x = 0, in m
const Vec3 particle_offset = half_extents;  // r_i(0): the particle is a corner of the box
constexpr double omega_scale = 0.8;         // m of arrow per rad/s
constexpr double velocity_scale = 0.8;      // m of arrow per m/s
constexpr double derivative_step = 1e-4;    // h of the central difference of R, in s

Mat3 rotation_at(double t) { return rodrigues(axis, spin * t); }  // eq. 1-4, θ = |ω| t

// What the figure shows at one instant.
struct State {
  Mat3 rotation;      // R(t)
  Vec3 r;             // r_i(t) = R(t) r_i(0), eq. 1-24 (x = 0)
  Vec3 r_dot;         // ṙ_i = ω × r_i, eq. 1-28
  double alpha;       // α, the angle between ω and r_i, in rad
  double speed;       // |sin α| |r_i| |ω|, in m/s: what |ṙ_i| must be (Fig 1-2, 1-3)
  double skew_error;  // max|Ṙ Rᵀ − Skew(ω)|, Ṙ by a central difference (eq. 1-27)
};

State state_at(double t) {
  State s;
  s.rotation = rotation_at(t);
  s.r = particle_position(Vec3::Zero(), s.rotation, particle_offset);
  s.r_dot = omega.cross(s.r);
  s.alpha = std::acos(omega.dot(s.r) / (omega.norm() * s.r.norm()));
  s.speed = std::abs(std::sin(s.alpha)) * s.r.norm() * omega.norm();
  const Mat3 r_dot_matrix =
      (rotation_at(t + derivative_step) - rotation_at(t - derivative_step)) / (2 * derivative_step);
  s.skew_error = (r_dot_matrix * s.rotation.transpose() - skew(omega)).cwiseAbs().maxCoeff();
  return s;
}

// The twelve edges of the box turned by R, as segments.
std::vector<std::vector<Vec3>> box_edges(const Mat3& rotation) {
  std::vector<std::vector<Vec3>> edges;
  for (int axis_index = 0; axis_index < 3; ++axis_index) {
    const int i = (axis_index + 1) % 3, j = (axis_index + 2) % 3;
    for (double si : {-1.0, 1.0}) {
      for (double sj : {-1.0, 1.0}) {
        Vec3 end = Vec3::Zero();
        end[i] = si * half_extents[i];
        end[j] = sj * half_extents[j];
        Vec3 start = end;
        start[axis_index] = -half_extents[axis_index];
        end[axis_index] = half_extents[axis_index];
        edges.push_back({rotation * start, rotation * end});
      }
    }
  }
  return edges;
}

class TurningParticle : public tutorial::Scene {
 public:
  tutorial::SceneInfo info() const override {
    return {"turning_particle", frame_dt, 61, 2, {Vec2(-2.6, -1.3), Vec2(4.9, 2.2)}};
  }

  void step() override { ++step_; }

  void draw(render::Frame& frame) const override {
    using namespace render::palette;
    const State s = state_at(step_ * frame_dt);
    frame.caption =
        tr("Ch 1 · Fig 1-2, 1-3: ṙᵢ = ω × rᵢ, |ṙᵢ| = |sin α| |rᵢ| |ω| (eq. 1-27, 1-28)");
    for (const std::vector<Vec3>& edge : box_edges(s.rotation)) {
      frame.paths3.push_back({edge, tint(grey, 0.6), false});
    }
    // The particle's circle: about the axis, at the height of r_i along it, radius |r_i| sin α.
    const Vec3 centre = s.r.dot(axis) * axis;
    const Vec3 across = s.r - centre;
    frame.paths3.push_back({{-1.1 * axis, 1.9 * axis}, grey, true});
    frame.paths3.push_back(
        {arc(centre, across.normalized(), axis.cross(across).normalized(), across.norm(), 2 * M_PI),
         sky_blue, false});
    frame.paths3.push_back({{centre, s.r}, grey, true});
    const tutorial::AngleMark mark = tutorial::angle_mark(Vec3::Zero(), omega, s.r, 0.3, 0.43);
    frame.paths3.push_back({mark.points, reddish_purple, false});
    frame.labels3.push_back({mark.label_at, "α", reddish_purple, render::Label::Align::centre});
    frame.arrows3.push_back({Vec3::Zero(), omega_scale * omega, ink, "ω"});
    frame.arrows3.push_back({Vec3::Zero(), s.r, blue, "rᵢ"});
    frame.arrows3.push_back({s.r, s.r + velocity_scale * s.r_dot, vermillion, "ṙᵢ"});
    frame.points3.push_back({Vec3::Zero(), ink, "x"});
    frame.points3.push_back({s.r, blue, ""});
    frame.legend = {
        {render::LegendEntry::Sample::arrow, ink, tr("ω: the body turns about ω/|ω| at |ω|")},
        {render::LegendEntry::Sample::arrow, blue, tr("particle rᵢ = R(t) rᵢ(0) (1-24)")},
        {render::LegendEntry::Sample::arrow, vermillion, "ṙᵢ = ω × rᵢ (1-28)"},
        {render::LegendEntry::Sample::line, sky_blue, tr("the circle rᵢ runs on, about the axis")},
        {render::LegendEntry::Sample::dashed_line, grey, tr("its radius |rᵢ| sin α")}};
    draw_world_axes(frame, Vec3(-1.8, -1.0, 0.0), 0.5);
    frame.panels.push_back(numbers_panel(s));
  }

  tutorial::Explanation explain() const override {
    const State s = state_at(step_ * frame_dt);
    return {{tr("A particle of the turning body"),
             {{"ω", "1-27", tr("angular velocity, Skew(ω) = Ṙ Rᵀ"), json_of(omega), "rad/s"},
              {"R", "1-4", tr("rotation by |ω| t about ω/|ω|"), json_of(s.rotation), ""},
              {"rᵢ", "1-24", tr("R(t) rᵢ(0), from the centre of mass"), json_of(s.r), "m"},
              {"α", "", tr("angle between ω and rᵢ"), s.alpha, "rad"},
              {"ṙᵢ", "1-28", "ω × rᵢ", json_of(s.r_dot), "m/s"},
              {"|ṙᵢ|", "", "|ω × rᵢ|", s.r_dot.norm(), "m/s"},
              {"|sin α| |rᵢ| |ω|", "", tr("the same speed, from α"), s.speed, "m/s"}}}};
  }

 private:
  static render::Panel numbers_panel(const State& s) {
    render::Panel panel;
    panel.corner = render::Corner::top_right;
    panel.title = tr("The particle in numbers");
    panel.lines = {"ω = " + fixed(omega) + " rad/s",
                   "rᵢ = R(t) rᵢ(0) = " + fixed(s.r) + " m  (1-24)",
                   "α = ∠(ω, rᵢ) = " + fixed(s.alpha) + " rad",
                   "ṙᵢ = ω × rᵢ = " + fixed(s.r_dot) + " m/s  (1-28)",
                   "|ṙᵢ| = " + fixed(s.r_dot.norm()) + " m/s",
                   "|sin α| |rᵢ| |ω| = " + fixed(s.speed) + " m/s",
                   "max|Ṙ Rᵀ − Skew(ω)| = " + tutorial::scientific(s.skew_error) + "  (1-27)",
                   tr("  (Ṙ by central difference, h = 1e-4 s)"),
                   fill(tr("arrows: ω {0} m per rad/s, ṙ {1} m per m/s"),
                        {fixed(omega_scale, 1), fixed(velocity_scale, 1)})};
    return panel;
  }

  long step_ = 0;  // frames since t = 0
};

}  // namespace

tutorial::SceneFactory turning_particle_scene() { return tutorial::scene<TurningParticle>(); }

}  // namespace lamina::ch1
