#include "ch3/one_sided_incline.h"

#include <cmath>
#include <string>
#include <vector>

#include "ch3/constrained_system.h"
#include "ch3/incline_geometry.h"
#include "ch3/sign_diagram.h"
#include "constraints/incline_constraint.h"
#include "language/language.h"

namespace lamina::ch3 {
namespace {

constexpr double throw_off = 3.0;      // the throw's speed along N, in m/s
constexpr double throw_along = 1.0;    // and down the slope, in m/s
constexpr double force_scale = 0.03;   // m of arrow per N
constexpr double longest_arrow = 1.5;  // a longer force arrow is cut to this, in m

class OneSidedIncline : public tutorial::Scene {
 public:
  OneSidedIncline()
      : diagram_(Vec2(11.0, 1.0), Vec2(5.0, 3.3), {250.0, 50.0, "λ (N)"},
                 {2000.0, 500.0, "W (m/s²)"}, tr("incline row"), SignDiagram::Caption::above) {
    RigidBody box = incline::box_on_line(1.0);
    box.v = spatial(throw_off * incline::normal + throw_along * incline::downhill);
    s_.bodies.push_back(box);
    // eq. 3-17: the centre may leave the line, not cross it
    s_.constraints.push_back(std::make_unique<InclineConstraint>(
        0, incline::line_point(), spatial(incline::normal), InclineKind::one_sided));
    step();
  }

  tutorial::SceneInfo info() const override {
    return {"one_sided_incline", 1.0 / 60.0, 46, 2, {Vec2(-0.6, -1.6), Vec2(17.4, 5.8)}};
  }

  void step() override {
    s_.step({incline::error(s_.bodies[0])});
    diagram_.record(lambda(), slack());
    trail_.push_back(planar(s_.at_t[0].x));
  }

  void draw(render::Frame& frame) const override {
    const RigidBody& box = s_.at_t[0];
    frame.caption =
        tr("Ch 3 · Fig 3-2, 3-3: a box that may leave the line, (x − p)·N ≥ 0 (eq. 3-17..3-22)");
    frame.force_scale = force_scale;
    incline::draw_line(frame, 12.0);
    frame.paths.push_back({trail_, tint(bluish_green, 0.6), false});
    frame.bodies.push_back(incline::box_view(box));
    const Vec2 x = planar(box.x);
    // unlabelled (the legend names it): a label at its tip would cross the line as the box nears it
    frame.arrows.push_back({x, x + force_scale * planar(box.mass * gravity), vermillion, "",
                            render::Overlay::forces});
    if (lambda() > 0.0) {
      const double length = std::min(force_scale * lambda(), longest_arrow);
      const std::string label =
          length < longest_arrow ? "λN" : fill(tr("λN (cut: {0} N)"), {fixed(lambda(), 0)});
      frame.arrows.push_back({x, x + length * incline::normal, blue, label, render::Overlay::forces});
    }
    diagram_.draw(frame);
    frame.panels.push_back(panel());
    frame.legend = {
        {render::LegendEntry::Sample::dashed_line, grey,
         tr("C = (x − p)·N = 0: the centre may not go below")},
        {render::LegendEntry::Sample::line, tint(bluish_green, 0.6), tr("path of the centre x")},
        {render::LegendEntry::Sample::arrow, vermillion, tr("weight m g")},
        {render::LegendEntry::Sample::arrow, blue, tr("F_c = Jᵀλ = λN, only a push (λ ≥ 0)")},
        {render::LegendEntry::Sample::swatch, reddish_purple,
         tr("(λ, W) of this step; the dots: the steps before")}};
    frame.legend_corner = render::Corner::bottom_right;
  }

  tutorial::Explanation explain() const override {
    return explain_system(s_, tr("Fig 3-2 one-sided incline"), rows());
  }
  void record(tutorial::ViewerStep& step) const override { record_system(s_, rows(), step); }

 private:
  static std::vector<std::string> rows() {
    return {tr("one-sided incline, C = (x − p)·N ≥ 0 (eq. 3-17)")};
  }
  double lambda() const { return s_.report.solution.lambda[0]; }
  double slack() const { return s_.report.slack()[0]; }

  render::Panel panel() const {
    const double C = incline::error(s_.at_t[0]);
    render::Panel panel;
    panel.corner = render::Corner::bottom_left;
    panel.title = lambda() > 0.0 ? tr("On the line: λ > 0, W = 0") : tr("Free: λ = 0, W ≥ 0");
    panel.lines = {
        "C = (x − p)·N ≥ 0   = " + fixed(C) + " m  (3-17)",
        std::string(C > 0.0 ? "ζ = −C/Δt (C > 0)  " : "ζ = −βC/Δt (C ≤ 0) ") + " = " +
            fixed(s_.report.mlcp.zeta(0)) + " m/s  (3-18, 3-19)",
        "λ ∈ [0, ∞)          = " + fixed(lambda(), 2) + " N  (3-20)",
        "W = (J B λ − η)     = " + fixed(slack(), 2) + " m/s²  (3-23)",
        "m g cos θ           = " +
            fixed(s_.at_t[0].mass * gravity.norm() * std::cos(incline::angle), 2) + " N"};
    return panel;
  }

  System s_;
  SignDiagram diagram_;      // Fig 3-3 with every step's (λ, W)
  std::vector<Vec2> trail_;  // the centre's positions, one per step up to t, in m
};

}  // namespace

tutorial::SceneFactory one_sided_incline_scene() { return tutorial::scene<OneSidedIncline>(); }

}  // namespace lamina::ch3
