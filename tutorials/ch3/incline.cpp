#include "ch3/incline.h"

#include <cmath>

#include "ch3/constrained_system.h"
#include "ch3/incline_geometry.h"
#include "constraints/incline_constraint.h"
#include "language/language.h"

namespace lamina::ch3 {
namespace {

using incline::downhill;
using incline::slope_top;
constexpr double incline_force_scale = 0.05;  // m of arrow per N

class Incline : public tutorial::Scene {
 public:
  Incline() {
    // The constraint holds the centre of mass on the line through p, half a box above the surface.
    s_.bodies.push_back(incline::box_on_line(1.0));
    s_.constraints.push_back(
        std::make_unique<InclineConstraint>(0, incline::line_point(), spatial(incline::normal)));
    step();
  }

  tutorial::SceneInfo info() const override {
    return {"incline", 1.0 / 60.0, 46, 2, {Vec2(-0.6, -0.8), Vec2(8.6, 4.4)}};
  }

  void step() override { s_.step({incline::error(s_.bodies[0])}); }

  void draw(render::Frame& frame) const override {
    const RigidBody& box = s_.at_t[0];
    frame.caption = tr("Ch 3 · Fig 3-1: a box held on an incline, (x − p)·N = 0 (eq. 3-1..3-4)");
    frame.force_scale = incline_force_scale;
    frame.velocity_scale = 0.15;
    // θ between the slope and the horizontal, where the surface meets y = 0
    const double foot = slope_top.y() / std::tan(incline::angle);
    frame.paths.push_back({{Vec2(foot - 1.6, 0.0), Vec2(foot + 1.8, 0.0)}, grey, true});
    frame.labels.push_back({Vec2(foot + 1.0, 0.12), "θ = 30°", ink, render::Label::Align::centre});
    // p and N, drawn on the line the constraint holds the centre on
    incline::draw_line(frame, 7.2);
    frame.bodies.push_back(incline::box_view(box));
    const Vec2 x = planar(box.x);
    const Vec2 weight = planar(box.mass * gravity),
               support = planar(lambda() * spatial(incline::normal));
    const double k = incline_force_scale;
    frame.arrows.push_back({x, x + k * weight, vermillion, "m g", render::Overlay::forces});
    frame.arrows.push_back({x, x + k * support, blue, "λN", render::Overlay::forces});
    frame.arrows.push_back(
        {x, x + k * (weight + support), bluish_green, "", render::Overlay::forces});
    frame.panels.push_back(panel());
    frame.legend = {
        {render::LegendEntry::Sample::arrow, vermillion, tr("weight m g")},
        {render::LegendEntry::Sample::arrow, blue, tr("constraint force F_c = Jᵀλ = λN (3-11)")},
        {render::LegendEntry::Sample::arrow, bluish_green,
         tr("m g + λN = m g sin θ down the slope")},
        {render::LegendEntry::Sample::dashed_line, grey, "C = (x − p)·N = 0"}};
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    return explain_system(s_, tr("Fig 3-1 incline"), rows());
  }
  void record(tutorial::ViewerStep& step) const override { record_system(s_, rows(), step); }

 private:
  static std::vector<std::string> rows() { return {tr("incline, C = (x − p)·N (eq. 3-1)")}; }
  double lambda() const { return s_.report.solution.lambda[0]; }
  static double speed(const RigidBody& box) { return planar(box.v).dot(downhill); }

  render::Panel panel() const {
    const RigidBody& box = s_.at_t[0];
    const double g = gravity.norm(), dt = s_.settings.step.dt;
    render::Panel panel;
    panel.corner = render::Corner::top_right;
    panel.title = tr("The incline in numbers");
    panel.lines = {"m = " + fixed(box.mass, 1) + " kg   θ = 30°   N = (" +
                       fixed(incline::normal.x()) + ", " + fixed(incline::normal.y()) + ")",
                   "C = (x − p)·N     = " + scientific(incline::error(box)) + " m  (3-1)"};
    const StepReport& r = s_.report;
    panel.lines.insert(
        panel.lines.end(),
        {"J = [Nᵀ 0ᵀ]   J M⁻¹ Jᵀ = 1/m = " + fixed(r.mlcp.d(0)) + " 1/kg",
         "ζ = −βC/Δt       = " + fixed(r.mlcp.zeta(0)) + " m/s  (3-14)",
         "η = ζ/Δt − J(V/Δt + M⁻¹F) = " + fixed(r.mlcp.eta(0)) + " m/s²  (3-16)",
         "λ = η / (J M⁻¹ Jᵀ) = " + fixed(lambda()) + " N  (3-3, 3-4)",
         fill(tr("m g cos θ        = {0} N  (theory)"),
              {fixed(box.mass * g * std::cos(incline::angle))}),
         fill(tr("a along slope    = {0} m/s²"), {fixed((speed(s_.bodies[0]) - speed(box)) / dt)}),
         fill(tr("g sin θ          = {0} m/s²  (theory)"), {fixed(g * std::sin(incline::angle))}),
         fill(tr("arrows: {0} m per N"), {fixed(incline_force_scale, 2)})});
    return panel;
  }

  System s_;
};

}  // namespace

tutorial::SceneFactory incline_scene() { return tutorial::scene<Incline>(); }

}  // namespace lamina::ch3
