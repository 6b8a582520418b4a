#include "ch3/chain.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "app/harness/plot.h"
#include "app/views/motion/body_view.h"
#include "app/views/constraints/constraint_view.h"
#include "ch3/constrained_system.h"
#include "constraints/revolute_joint.h"
#include "language/language.h"

namespace lamina::ch3 {
namespace {

constexpr int links = 4;
const Vec2 link_half(0.25, 0.05);       // half extents of a link, in m
constexpr double link_density = 20.0;   // kg/m²: 1 kg per link
const Vec3 chain_pivot(0.0, 0.0, 0.0);  // the world pin, in m
constexpr double chain_release = 1.2;   // the straight chain's angle from hanging, in rad
const Vec3 chain_direction(std::sin(chain_release), -std::cos(chain_release), 0.0);  // unit
constexpr int comparison_step = 30;    // the step pgs_residual.png shows (from t = 0.5 s)
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
    settings.step.iterations = sweeps;
    constrained_step(bodies, s.constraints, settings, start, warm ? &c.warm : &c.cold);
  }
  return c;
}

class Chain : public tutorial::Scene {
 public:
  Chain() : s_(make_chain()), pins_(chain_pins(level_links())) { step(); }

  tutorial::SceneInfo info() const override {
    return {"chain", 1.0 / 60.0, 91, 2, {Vec2(-3.3, -2.3), Vec2(3.3, 1.1)}};
  }

  // Takes the next step, and the same step from λ = 0 for the panel; the trail gains the free
  // end's position at its t.
  void step() override {
    cold_residual_ =
        compare_warm_and_cold(s_, s_.settings.step.iterations).cold.solution.residuals.back();
    s_.step(joint_errors(s_.bodies, pins_));
    trail_.push_back(tip());
  }

  void draw(render::Frame& frame) const override {
    frame.caption =
        tr("Ch 3 · A chain on revolute joints: J B λ = η solved by PGS (eq. 3-16, 3-24)");
    frame.paths.push_back({trail_, tint(bluish_green, 0.6), false});
    frame.bodies.push_back(mount(chain_pivot));
    const render::Colour fills[] = {render::palette::sky_blue, orange, reddish_purple,
                                    bluish_green};
    for (int i = 0; i < links; ++i) {
      frame.bodies.push_back(view::box_view(s_.at_t[static_cast<std::size_t>(i)], link_half,
                                            tint(fills[i], 0.45)));
    }
    for (const auto& joint : s_.constraints) frame.joints.push_back(*view::joint_view(s_.at_t, *joint));
    frame.panels.push_back(panel());
    frame.legend = {{render::LegendEntry::Sample::line, tint(bluish_green, 0.6),
                     tr("path of the chain's free end")}};
    frame.legend_corner = render::Corner::bottom_left;
  }

  tutorial::Explanation explain() const override {
    return explain_system(s_, tr("Chain"), row_names());
  }
  void record(tutorial::ViewerStep& step) const override { record_system(s_, row_names(), step); }

  // The rows: each joint's x and y rows, from the world pin down.
  static std::vector<std::string> row_names() {
    std::vector<std::string> names;
    for (int i = 0; i < links; ++i) {
      const std::string joint =
          i == 0 ? std::string(tr("world pin – link 0"))
                 : fill(tr("link {0} – link {1}"), {std::to_string(i - 1), std::to_string(i)});
      names.push_back(fill(tr("{0}, x row: C = x̂·(p_b − p_a)"), {joint}));
      names.push_back(fill(tr("{0}, y row: C = ŷ·(p_b − p_a)"), {joint}));
    }
    return names;
  }

  // pgs_residual.png: a fresh chain up to t = comparison_step Δt, then that step from both guesses.
  void write_data(const std::filesystem::path& folder) const override {
    System s = make_chain();
    const Pins pins = chain_pins(level_links());
    for (int i = 0; i < comparison_step; ++i) s.step(joint_errors(s.bodies, pins));
    const Comparison c = compare_warm_and_cold(s, comparison_sweeps);
    std::vector<std::vector<double>> rows;
    for (int k = 0; k < comparison_sweeps; ++k) {
      const auto i = static_cast<std::size_t>(k);
      rows.push_back({k + 1.0, c.warm.solution.residuals[i], c.cold.solution.residuals[i]});
    }
    tutorial::write_plot(
        folder,
        {"pgs_residual",
         tr("Chain of 4 links, step 30 (t = 0.5 s): PGS residual per sweep (eq. 3-23, 3-24)"),
         tr("sweep"),
         tr("‖W‖ (m/s²), log scale"),
         {{tr("from last step's λ (warm start)"), bluish_green, false},
          {tr("from λ = 0"), vermillion, false}},
         rows,
         "top right",
         true});
  }

 private:
  // The free end of the last link at t.
  Vec2 tip() const {
    const RigidBody& last = s_.at_t.back();
    return planar(last.x + last.rotation * Vec3(link_half.x(), 0.0, 0.0));
  }

  render::Panel panel() const {
    double worst_gap = 0.0;
    const std::vector<double> C = joint_errors(s_.at_t, pins_);
    for (std::size_t k = 0; k < C.size(); k += 2)
      worst_gap = std::max(worst_gap, std::hypot(C[k], C[k + 1]));
    render::Panel panel;
    panel.corner = render::Corner::top_left;
    panel.title = tr("PGS on the chain (4 joints, 8 rows)");
    panel.lines = {"J: 8 × 24 (3-8)   J B: 8 × 8 (3-16)",
                   fill(tr("widest joint gap |p_b − p_a| = {0} m"), {fixed(worst_gap, 4)})};
    const int sweeps = s_.report.solution.iterations;
    panel.lines.push_back(fill(tr("‖W‖ after {0} sweeps (3-23, 3-24):"), {std::to_string(sweeps)}));
    panel.lines.push_back(
        fill(tr("  from last step's λ  {0} m/s²"), {scientific(s_.last_residual())}));
    panel.lines.push_back(fill(tr("  from λ = 0          {0} m/s²"), {scientific(cold_residual_)}));
    return panel;
  }

  System s_;
  Pins pins_;                   // each joint's anchors, the world pin first
  std::vector<Vec2> trail_;     // the free end's positions, one per step up to t, in m
  double cold_residual_ = 0.0;  // ‖W‖ of step k had PGS started from λ = 0, in m/s²
};

}  // namespace

tutorial::SceneFactory chain_scene() { return tutorial::scene<Chain>(); }

}  // namespace lamina::ch3
