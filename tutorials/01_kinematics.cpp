// Chapter 1 — kinematics. Three scenes; the motion is prescribed, not integrated (chapter 2
// integrates):
//   rodrigues_frame   Fig 1-1 in space: v turned about the unit axis d in the frame a, b, d
//                     (eq. 1-4, 1-6, 1-9; ch1/rodrigues_frame.h).
//   turning_particle  Fig 1-2, 1-3 in space: a particle r_i of a turning body, ṙ_i = ω × r_i and
//                     |ṙ_i| = |sin α| |r_i| |ω| (eq. 1-27, 1-28; ch1/turning_particle.h).
//   rotating_box      a box turns about z at constant ω while its centre drifts at v. Each frame
//                     draws the particle velocities v_i = v + ω × r_i (eq. 1-30) at the corners,
//                     the decomposition v + ω × r₁ at corner 1, and the rotation as the text
//                     builds it: Rodrigues (eq. 1-4) and the quaternion (eq. 1-19, 1-22).
#include <array>
#include <cmath>

#include "app/harness/format.h"
#include "app/harness/tutorial.h"
#include "ch1/rodrigues_frame.h"
#include "ch1/turning_particle.h"
#include "kinematics/inertia.h"
#include "kinematics/momentum.h"
#include "kinematics/particle.h"
#include "kinematics/quaternion.h"
#include "kinematics/rotation.h"
#include "language/language.h"

namespace {

using namespace lamina;
using lamina::tutorial::fixed;
using lamina::tutorial::Json;

constexpr double dt = 1.0 / 30.0;  // time between frames, in s
constexpr double half_x = 1.0;     // box half extents, in m
constexpr double half_y = 0.5;
constexpr double density = 1.0;      // kg/m² (1 m deep, see inertia.h)
const Vec3 start(-1.0, 0.0, 0.0);    // centre at t = 0, in m
const Vec3 velocity(0.5, 0.0, 0.0);  // v, in m/s
const Vec3 axis = Vec3::UnitZ();     // d, the rotation axis (unit)
const double spin = M_PI / 2.0;      // |ω|, in rad/s: one turn in 4 s

// Everything chapter 1 computes about the box at one instant.
struct State {
  double theta;                  // θ = |ω| t, in rad
  Vec3 x;                        // centre of mass, in m
  Vec3 omega;                    // ω = |ω| d, in rad/s
  Mat3 rodrigues_R;              // eq. 1-4
  Quat q;                        // eq. 1-19
  Mat3 quaternion_R;             // eq. 1-22
  Mat3 inertia;                  // I(t), eq. 1-37
  std::array<Vec3, 4> r;         // r_i(t) = R r_i(0), eq. 1-24
  std::array<Vec3, 4> corner;    // x_i(t), eq. 1-25
  std::array<Vec3, 4> corner_v;  // v_i, eq. 1-30
  double energy;                 // E, eq. 1-47
};

const double mass = density * 4.0 * half_x * half_y;
const std::array<Vec3, 4> body_corners{Vec3(half_x, half_y, 0), Vec3(-half_x, half_y, 0),
                                       Vec3(-half_x, -half_y, 0), Vec3(half_x, -half_y, 0)};

State state_at(double t) {
  State s;
  s.theta = spin * t;
  s.x = start + velocity * t;
  s.omega = spin * axis;
  s.rodrigues_R = rodrigues(axis, s.theta);
  s.q = quaternion_from_axis_angle(axis, s.theta);
  s.quaternion_R = quaternion_to_matrix(s.q);
  s.inertia = world_inertia(s.rodrigues_R, box_inertia(mass, half_x, half_y));
  for (std::size_t i = 0; i < 4; ++i) {
    s.corner[i] = particle_position(s.x, s.rodrigues_R, body_corners[i]);
    s.r[i] = s.corner[i] - s.x;
    s.corner_v[i] = particle_velocity(velocity, s.omega, s.x, s.corner[i]);
  }
  s.energy = kinetic_energy(mass, velocity, s.inertia, s.omega);
  return s;
}

Vec2 planar(const Vec3& v) { return v.head<2>(); }

class RotatingBox : public tutorial::Scene {
 public:
  tutorial::SceneInfo info() const override {
    return {"rotating_box", dt, 121, 1, {Vec2(-3.3, -2.45), Vec2(5.8, 2.45)}};
  }

  void step() override { ++step_; }

  void draw(render::Frame& frame) const override {
    const State s = state_at(step_ * dt);
    const double k = frame.velocity_scale = 0.5;  // m of arrow per m/s
    frame.caption =
        tr("Ch 1 · A turning box: each particle moves at vᵢ = v + ω × rᵢ (eq. 1-30)");
    render::Body box;
    box.centre = planar(s.x);
    box.angle = s.theta;
    box.half_extents = {half_x, half_y};
    box.velocity = planar(velocity);
    frame.bodies.push_back(box);
    const char* names[] = {"v₁", "v₂", "v₃", "v₄"};
    for (std::size_t i = 0; i < 4; ++i) {
      frame.arrows.push_back({planar(s.corner[i]), planar(s.corner[i] + k * s.corner_v[i]),
                              render::palette::vermillion, names[i], std::nullopt});
    }
    // Corner 1: v, then ω × r₁ from its tip, ending where v₁ ends (eq. 1-30 as a vector sum).
    const Vec3 v_tip = s.corner[0] + k * velocity;
    frame.arrows.push_back(
        {planar(s.corner[0]), planar(v_tip), render::palette::blue, "", std::nullopt});
    const Vec3 turn = k * s.omega.cross(s.r[0]);
    frame.arrows.push_back(
        {planar(v_tip), planar(v_tip + turn), render::palette::reddish_purple, "", std::nullopt});
    // Its label sits beside the middle of the arrow, on the side away from the box.
    const Vec3 middle = v_tip + 0.5 * turn;
    frame.labels.push_back({planar(middle + 0.3 * (middle - s.x).normalized()), "ω × r₁",
                            render::palette::reddish_purple, render::Label::Align::centre});
    frame.panels.push_back(numbers_panel(s));
    frame.legend = {{render::LegendEntry::Sample::arrow, render::palette::vermillion,
                     tr("particle velocity vᵢ = v + ω × rᵢ (1-30)")},
                    {render::LegendEntry::Sample::arrow, render::palette::reddish_purple,
                     "ω × r₁ = Ṙ Rᵀ r₁ (1-28)"}};
  }

  tutorial::Explanation explain() const override {
    const State s = state_at(step_ * dt);
    tutorial::Explanation e;
    e.push_back(
        {tr("Rotation about d by θ"),
         {{"θ", "", tr("angle turned, |ω| t"), s.theta, "rad"},
          {"d", "", tr("unit rotation axis"), tutorial::json_of(axis), ""},
          {"Skew(d)", "1-2", tr("cross-product matrix, Skew(d) r = d × r"),
           tutorial::json_of(skew(axis)), ""},
          {"R", "1-4", "Rodrigues: E + sinθ Skew(d) + (1 − cosθ) Skew(d)²",
           tutorial::json_of(s.rodrigues_R), ""},
          {"q", "1-19", "cos(θ/2) + d sin(θ/2)", tutorial::json_of(s.q), ""},
          {"R(q)", "1-22", tr("the matrix of q; equals R"), tutorial::json_of(s.quaternion_R),
           ""}}});
    e.push_back(
        {tr("The body"),
         {{"x", "1-25", tr("centre of mass, x(0) + v t"), tutorial::json_of(s.x), "m"},
          {"v", "1-38", tr("linear velocity (P = m v)"), tutorial::json_of(velocity), "m/s"},
          {"ω", "1-27", tr("angular velocity, Skew(ω) = Ṙ Rᵀ"), tutorial::json_of(s.omega),
           "rad/s"},
          {"I(t)", "1-37", tr("world inertia R I(0) Rᵀ"), tutorial::json_of(s.inertia), "kg·m²"},
          {"L", "1-41", tr("angular momentum I ω"),
           tutorial::json_of(angular_momentum(s.inertia, s.omega)), "kg·m²/s"},
          {"E", "1-47", tr("kinetic energy ½ m vᵀv + ½ ωᵀ I ω"), s.energy, "J"}}});
    tutorial::Section corners{tr("Corner particles"), {}};
    for (std::size_t i = 0; i < 4; ++i) {
      const std::string n = std::to_string(i + 1);
      corners.quantities.push_back(
          {"r" + n, "1-24", tr("R rᵢ(0), from the centre"), tutorial::json_of(s.r[i]), "m"});
      corners.quantities.push_back(
          {"v" + n, "1-30", "v + ω × rᵢ", tutorial::json_of(s.corner_v[i]), "m/s"});
    }
    e.push_back(corners);
    return e;
  }

 private:
  static render::Panel numbers_panel(const State& s) {
    render::Panel panel;
    panel.corner = render::Corner::top_right;
    panel.title = tr("The rotation in numbers");
    panel.lines.push_back("θ = " + fixed(s.theta) + " rad   d = (0, 0, 1)");
    panel.lines.push_back("R = E + sinθ Skew(d)");
    panel.lines.push_back("    + (1−cosθ) Skew(d)²   (1-4)");
    for (const std::string& row : tutorial::fixed_rows(s.rodrigues_R))
      panel.lines.push_back("    " + row);
    panel.lines.push_back("q = cos(θ/2) + d sin(θ/2) (1-19)");
    panel.lines.push_back("  = " + fixed(s.q.w()) + " + " + fixed(s.q.vec()));
    panel.lines.push_back(
        "max|R(q) − R| = " +
        tutorial::scientific((s.quaternion_R - s.rodrigues_R).cwiseAbs().maxCoeff()) + "  (1-22)");
    panel.lines.push_back("ω = " + fixed(s.omega, 2) + " rad/s");
    panel.lines.push_back("v = " + fixed(velocity, 2) + " m/s");
    panel.lines.push_back(fill(tr("E = ½mvᵀv + ½ωᵀIω = {0} J (1-47)"), {fixed(s.energy, 2)}));
    panel.lines.push_back(tr("arrows: 0.5 m per m/s"));
    return panel;
  }

  long step_ = 0;  // frames since t = 0
};

}  // namespace

int main(int argc, char** argv) {
  const tutorial::TutorialInfo info{
      "01_kinematics",
      "ch1",
      "Chapter 1: Rodrigues' frame (Fig 1-1), a turning particle (Fig 1-2, 1-3), and a turning "
      "box with its particle velocities and its rotation as R and q",
      {render::Overlay::velocities, render::Overlay::centres}};
  return tutorial::run_tutorial(argc, argv, info,
                                {ch1::rodrigues_frame_scene(), ch1::turning_particle_scene(),
                                 tutorial::scene<RotatingBox>()});
}
