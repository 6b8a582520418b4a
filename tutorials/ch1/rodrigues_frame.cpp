#include "ch1/rodrigues_frame.h"

#include <cmath>

#include "app/harness/format.h"
#include "app/harness/sketch3d.h"
#include "kinematics/rotation.h"
#include "language/language.h"

namespace lamina::ch1 {
namespace {

using tutorial::arc;
using tutorial::draw_world_axes;
using tutorial::fixed;
using tutorial::json_of;

constexpr double dt = 1.0 / 30.0;       // time between frames, in s
constexpr double turn_rate = M_PI / 2;  // θ grows by π/2 rad per s: one turn in 4 s
// The frame of the figure: d, the rotation axis, leans out of the y axis; a is the part of x
// across d, and b = d × a, so that [a b d] is a rotation (a × b = d).
const Vec3 d = Vec3(0.25, 1.0, 0.1).normalized();
const Vec3 a = (Vec3::UnitX() - Vec3::UnitX().dot(d) * d).normalized();
const Vec3 b = d.cross(a);
// v in the frame's coordinates, eq. 1-9: v = (a·v) a + (b·v) b + (d·v) d.
constexpr double v_along_a = 1.1, v_along_d = 1.8;
const Vec3 v = v_along_a * a + v_along_d * d;

// eq. 1-6: R = [a b d] Rz(θ) [a b d]ᵀ, with Rz(θ) of eq. 1-5: the rotation taken into the frame
// where d is z, turned about z, and taken back. ([a b d]⁻¹ = [a b d]ᵀ: it is a rotation.)
Mat3 rotation_in_frame(double theta) {
  Mat3 abd;
  abd << a, b, d;
  return abd * rotation_z(theta) * abd.transpose();
}

class RodriguesFrame : public tutorial::Scene {
 public:
  tutorial::SceneInfo info() const override {
    return {"rodrigues_frame", dt, 61, 2, {Vec2(-2.5, -1.3), Vec2(4.7, 2.55)}};
  }

  void step() override { ++step_; }

  void draw(render::Frame& frame) const override {
    using namespace render::palette;
    const double theta = theta_now();
    const Vec3 turned = rodrigues(d, theta) * v;  // eq. 1-4
    const Vec3 centre = v_along_d * d;            // the circle's centre on the axis
    frame.caption =
        tr("Ch 1 · Fig 1-1: v turned by θ about d, in the frame a, b, d (eq. 1-4, 1-6)");
    frame.paths3.push_back({{-0.4 * d, 2.5 * d}, grey, true});  // the axis
    frame.paths3.push_back({arc(centre, a, b, v_along_a, 2 * M_PI), grey, false});
    frame.paths3.push_back({{centre, v}, grey, true});
    frame.paths3.push_back({{centre, turned}, grey, true});
    // θ from a, the direction of v across d, towards b: the turn of eq. 1-6 in the a–b plane
    frame.paths3.push_back({arc(centre, a, b, 0.45, theta), reddish_purple, false});
    const Vec3 middle = centre + 0.65 * (std::cos(0.5 * theta) * a + std::sin(0.5 * theta) * b);
    frame.labels3.push_back({middle, "θ", reddish_purple, render::Label::Align::centre});
    frame.arrows3.push_back({Vec3::Zero(), a, ink, "a"});
    frame.arrows3.push_back({Vec3::Zero(), b, ink, "b"});
    frame.arrows3.push_back({Vec3::Zero(), d, ink, "d"});
    // near θ = 0 and 2π the two tips meet: one label names both (labels never cover each other)
    const bool one_tip = (turned - v).norm() < 0.3;
    frame.arrows3.push_back({Vec3::Zero(), v, blue, one_tip ? "v, R v" : "v"});
    frame.arrows3.push_back({Vec3::Zero(), turned, vermillion, one_tip ? "" : "R v"});
    frame.points3.push_back({centre, ink, ""});
    frame.legend = {
        {render::LegendEntry::Sample::arrow, ink, tr("a, b, d: orthonormal, d the axis")},
        {render::LegendEntry::Sample::arrow, blue, "v"},
        {render::LegendEntry::Sample::arrow, vermillion, tr("R v, turned by θ about d")},
        {render::LegendEntry::Sample::line, grey, tr("the circle v's tip turns on")},
        {render::LegendEntry::Sample::point, ink, tr("its centre (d·v) d, on the axis")}};
    draw_world_axes(frame, Vec3(-2.0, -0.9, 0.0), 0.6);
    frame.legend_corner = render::Corner::bottom_right;
    frame.panels.push_back(numbers_panel(theta, turned));
  }

  tutorial::Explanation explain() const override {
    const double theta = theta_now();
    const Mat3 r = rodrigues(d, theta);
    return {{tr("The frame a, b, d"),
             {{"d", "", tr("unit rotation axis"), json_of(d), ""},
              {"a", "", tr("unit, across d"), json_of(a), ""},
              {"b", "", tr("d × a, so that [a b d] is a rotation"), json_of(b), ""},
              {"θ", "", tr("angle turned, θ = (π/2 rad/s) t"), theta, "rad"}}},
            {tr("The rotation"),
             {{"R", "1-4", "E + sinθ Skew(d) + (1 − cosθ) Skew(d)²", json_of(r), ""},
              {"R", "1-6", "[a b d] Rz(θ) [a b d]ᵀ", json_of(rotation_in_frame(theta)), ""},
              {"v", "1-9", "(a·v) a + (b·v) b + (d·v) d", json_of(v), ""},
              {"R v", "1-4", tr("v turned by θ about d"), json_of(Vec3(r * v)), ""}}}};
  }

 private:
  double theta_now() const { return turn_rate * step_ * dt; }

  static render::Panel numbers_panel(double theta, const Vec3& turned) {
    const double gap = (rotation_in_frame(theta) - rodrigues(d, theta)).cwiseAbs().maxCoeff();
    render::Panel panel;
    panel.corner = render::Corner::top_right;
    panel.title = tr("Rodrigues in numbers");
    panel.lines = {"θ = " + fixed(theta) + " rad",
                   "d = " + fixed(d),
                   "a = " + fixed(a),
                   "b = d × a = " + fixed(b),
                   "v = (a·v) a + (b·v) b + (d·v) d  (1-9)",
                   "  = " + fixed(v_along_a, 1) + " a + 0 b + " + fixed(v_along_d, 1) + " d",
                   "R = E + sinθ Skew(d)",
                   "    + (1−cosθ) Skew(d)²  (1-4)",
                   "R v = " + fixed(turned),
                   "R = [a b d] Rz(θ) [a b d]ᵀ  (1-6)",
                   "max|R(1-6) − R(1-4)| = " + tutorial::scientific(gap),
                   "|R v| = " + fixed(turned.norm()) + " = |v|"};
    return panel;
  }

  long step_ = 0;  // frames since t = 0
};

}  // namespace

tutorial::SceneFactory rodrigues_frame_scene() { return tutorial::scene<RodriguesFrame>(); }

}  // namespace lamina::ch1
