#include "ch3/angle_limit.h"

#include <array>
#include <cmath>
#include <vector>

#include "app/views/constraints/constraint_view.h"
#include "app/views/motion/body_view.h"
#include "ch3/constrained_system.h"
#include "ch3/sign_diagram.h"
#include "constraints/angle_limit.h"
#include "constraints/revolute_joint.h"
#include "language/language.h"

namespace lamina::ch3 {
namespace {

const Vec2 bar_half(0.6, 0.05);              // half extents of the bar, in m
constexpr double bar_density = 1.0 / 0.12;   // kg/m²: m = 1 kg
const Vec3 hinge(0.0, 0.0, 0.0);             // the world pin, in m
constexpr double limit = -M_PI / 2.0 - 0.5;  // θ_L: 0.5 rad past hanging (θ = −π/2), in rad
constexpr double limit_ray = 1.4;            // how long the limit is drawn, in m

class AngleLimitScene : public tutorial::Scene {
 public:
  AngleLimitScene()
      : diagram_(Vec2(2.5, -0.7), Vec2(2.3, 1.55), {120.0, 20.0, "λ (N·m)"},
                 {8000.0, 2000.0, "W (rad/s²)"}, tr("angle-limit row"),
                 SignDiagram::Caption::below) {
    // the bar level, pointing along +x from the pin: θ = 0
    const Vec3 centre = hinge + Vec3(bar_half.x(), 0.0, 0.0);
    s_.bodies.push_back(box_body(bar_density, bar_half.x(), bar_half.y(), centre));
    pin_ = {anchor_at(s_.bodies, world, hinge), anchor_at(s_.bodies, 0, hinge)};
    s_.constraints.push_back(std::make_unique<RevoluteJoint>(pin_[0], pin_[1]));
    s_.constraints.push_back(std::make_unique<AngleLimit>(world, 0, limit, LimitSide::lower));
    step();
  }

  tutorial::SceneInfo info() const override {
    return {"angle_limit", 1.0 / 60.0, 91, 2, {Vec2(-1.7, -2.45), Vec2(5.7, 1.3)}};
  }

  void step() override {
    const RigidBody& bar = s_.bodies[0];
    const Vec3 gap = anchor_position(s_.bodies, pin_[1]) - anchor_position(s_.bodies, pin_[0]);
    // C of the pin's x and y rows, and of the limit, θ − θ_L ≥ 0 (eq. 3-17 for an angle)
    s_.step({gap.x(), gap.y(), planar_angle(bar.q) - limit});
    diagram_.record(lambda(), slack());
    trail_.push_back(tip());
  }

  void draw(render::Frame& frame) const override {
    frame.caption =
        tr("Ch 3 · A hinge with an angle limit, θ − θ_L ≥ 0: an inequality row (eq. 3-17..3-22)");
    const Vec2 pivot = planar(hinge), ray(std::cos(limit), std::sin(limit));
    frame.paths.push_back({{pivot, pivot + limit_ray * ray}, vermillion, true});
    frame.labels.push_back(
        {pivot + (limit_ray + 0.1) * ray, "θ_L", vermillion, render::Label::Align::right});
    frame.paths.push_back({{pivot, pivot + Vec2(0.0, -limit_ray)}, grey, true});
    frame.paths.push_back({trail_, tint(bluish_green, 0.6), false});
    frame.bodies.push_back(mount(hinge));
    frame.bodies.push_back(view::box_view(s_.at_t[0], bar_half, tint(orange, 0.45)));
    frame.joints.push_back(*view::joint_view(s_.at_t, *s_.constraints[0]));
    diagram_.draw(frame);
    frame.panels.push_back(panel());
    frame.legend = {{render::LegendEntry::Sample::dashed_line, vermillion,
                     tr("the limit θ = θ_L = −π/2 − 0.5 rad")},
                    {render::LegendEntry::Sample::dashed_line, grey, tr("hanging, θ = −π/2")},
                    {render::LegendEntry::Sample::line, tint(bluish_green, 0.6),
                     tr("path of the bar's free end")},
                    {render::LegendEntry::Sample::swatch, reddish_purple,
                     tr("(λ, W) of this step; the dots: the steps before")}};
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    return explain_system(s_, tr("Angle limit"), rows());
  }
  void record(tutorial::ViewerStep& step) const override { record_system(s_, rows(), step); }

 private:
  // the rows are written in the constraints' order: the pin's x and y rows, then the limit's
  static std::vector<std::string> rows() {
    return {fill(tr("{0}, x row: C = x̂·(p_b − p_a)"), {tr("pin")}),
            fill(tr("{0}, y row: C = ŷ·(p_b − p_a)"), {tr("pin")}),
            tr("angle limit, C = θ − θ_L ≥ 0 (eq. 3-17)")};
  }
  static constexpr int limit_row = 2;
  double lambda() const { return s_.report.solution.lambda[limit_row]; }
  double slack() const { return s_.report.slack()[limit_row]; }
  // The bar's free end at t.
  Vec2 tip() const {
    const RigidBody& bar = s_.at_t[0];
    return planar(bar.x + bar.rotation * Vec3(bar_half.x(), 0.0, 0.0));
  }

  render::Panel panel() const {
    const double theta = planar_angle(s_.at_t[0].q);
    render::Panel panel;
    panel.corner = render::Corner::top_left;
    panel.title = lambda() > 0.0 ? tr("At the limit: λ > 0, W = 0") : tr("Free: λ = 0, W ≥ 0");
    panel.lines = {"θ = " + fixed(theta) + " rad   θ_L = " + fixed(limit) + " rad",
                   "C = θ − θ_L ≥ 0 = " + fixed(theta - limit) + " rad  (3-17)",
                   "ζ = " + fixed(s_.report.mlcp.zeta(limit_row), 2) + " rad/s  (3-18, 3-19)",
                   "λ = " + fixed(lambda(), 2) + " N·m  (3-20)",
                   "W = " + fixed(slack(), 2) + " rad/s²  (3-23)"};
    return panel;
  }

  System s_;
  std::array<Anchor, 2> pin_;  // the pin's two anchors: the world point and the bar's end
  std::vector<Vec2> trail_;    // the free end's positions, one per step up to t, in m
  SignDiagram diagram_;        // Fig 3-3 with every step's (λ, W) of the limit row
};

}  // namespace

tutorial::SceneFactory angle_limit_scene() { return tutorial::scene<AngleLimitScene>(); }

}  // namespace lamina::ch3
