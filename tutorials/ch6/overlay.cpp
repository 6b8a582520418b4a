#include "ch6/overlay.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "app/harness/format.h"
#include "app/harness/plot.h"
#include "app/views/contact/world_explanation.h"
#include "app/views/contact/stepped_world.h"
#include "beyond/methods.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina::ch6 {
namespace {

using tutorial::fixed;

constexpr int every = 20;  // steps between frames: 31 frames show t = 0 … 10 s

render::Body body_at(const BodyDescription& d, const Pose& pose, render::Colour fill) {
  render::Body b;
  b.shape = d.shape.type == ShapeType::circle ? render::Body::Shape::circle : render::Body::Shape::box;
  b.centre = pose.head<2>();
  b.angle = pose.z();
  b.half_extents = d.shape.half_extents;
  b.radius = d.shape.radius;
  b.fill = fill;
  b.fixed = d.is_static;
  return b;
}

// What the scene's plot follows: its measure at a sample, in the plot's units.
double followed(const TableScene& s, const LabSample& x) {
  if (s.scene.rfind("heavy-on-light", 0) == 0) return 1000.0 * x.overlap;  // mm
  if (s.scene == "ball-and-chain:100") return 100.0 * x.stretch;           // %
  return x.top;                                                            // m
}

// A logarithmic plot shows a holding run (nm, or round-off) beside a falling one (metres); a
// value below 1 µm is drawn at 1 µm. The chain's stretch, which may be negative, stays linear.
bool log_plot(const TableScene& s) { return s.scene != "ball-and-chain:100"; }
double micrometre(const TableScene& s) { return s.scene.rfind("heavy-on-light", 0) == 0 ? 1e-3 : 1e-6; }

std::string followed_name(const TableScene& s) {
  if (s.scene.rfind("heavy-on-light", 0) == 0) return "deepest overlap (mm)";
  if (s.scene == "ball-and-chain:100") return "pin to ball past its rest length (%)";
  if (s.scene == "vertical-stack:20") return "top box moved (m)";
  return "apex moved (m)";
}

class Overlay : public tutorial::Scene {
 public:
  explicit Overlay(TableScene scene) : table_(std::move(scene)), scene_(builtin_scene(table_.scene)) {}

  tutorial::SceneInfo info() const override {
    return {table_.stem, scene_.step.dt, lab_steps / every + 1, every, view()};
  }

  void step() override { ++step_; }

  void draw(render::Frame& frame) const override {
    const std::vector<LabRun>& runs = lab_runs(table_);
    frame.caption = "Chapter 6 · " + table_.scene + " by Box2D 2.4.1 and each of Lamina's methods, overlaid";
    for (std::size_t b = 0; b < scene_.bodies.size(); ++b) {
      if (scene_.bodies[b].is_static) {
        frame.bodies.push_back(body_at(scene_.bodies[b], runs[0].poses[0][b], render::palette::grid));
      }
    }
    render::Panel panel;
    panel.corner = render::Corner::top_left;
    panel.title = "largest so far: " + followed_name(table_);
    for (std::size_t c = 0; c < runs.size(); ++c) {
      const LabRun& run = runs[c];
      const Contender& who = contenders()[c];
      // the state at t = step_ Δt; a run that diverged stays drawn where it was last finite
      const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(step_), run.poses.size() - 1);
      for (std::size_t b = 0; b < scene_.bodies.size(); ++b) {
        if (scene_.bodies[b].is_static) continue;
        frame.bodies.push_back(body_at(scene_.bodies[b], run.poses[k][b],
                                       render::with_alpha(tint(who.colour, 0.7), 110)));
      }
      frame.legend.push_back({render::LegendEntry::Sample::swatch, who.colour, who.name});
      double most = 0.0;  // over the samples up to the state shown
      for (std::size_t i = 0; i < k; ++i) most = std::max(most, followed(table_, run.samples[i]));
      std::string line = who.name;
      line.resize(std::max<std::size_t>(line.size(), 12), ' ');
      const bool gone = run.diverged && k + 1 == run.poses.size() && static_cast<std::size_t>(step_) >= k + 1;
      panel.lines.push_back(line + (gone ? "diverged" : fixed(most, 3)));
    }
    frame.panels.push_back(panel);
    frame.legend_corner = render::Corner::top_right;
  }

  // The scene's region, grown to hold every moving body of every run at every step (bodies thrown
  // out of it would be drawn over the caption), with 0.3 m to spare.
  render::Rect view() const {
    render::Rect r = table_.view;
    for (const LabRun& run : lab_runs(table_)) {
      for (const std::vector<Pose>& poses : run.poses) {
        for (std::size_t b = 0; b < poses.size(); ++b) {
          const BodyDescription& d = scene_.bodies[b];
          if (d.is_static) continue;
          const double reach = 0.3 + (d.shape.type == ShapeType::circle ? d.shape.radius : d.shape.half_extents.norm());
          r.min = r.min.cwiseMin(poses[b].head<2>() - Vec2(reach, reach));
          r.max = r.max.cwiseMax(poses[b].head<2>() + Vec2(reach, reach));
        }
      }
    }
    return r;
  }

  tutorial::Explanation explain() const override {
    // What `islands`, the default, solved in this step: the World stepped again to it (the
    // table's runs keep poses, not reports).
    lamina::Scene scene = scene_;
    scene.solver = default_method;
    view::SteppedWorld world(build_world(scene, world_settings(scene)));
    for (long k = 0; k <= step_; ++k) world.step();
    std::vector<std::string> names;
    for (const BodyDescription& b : scene_.bodies) names.push_back(b.name);
    return view::explain_world_step(world.world(), world.report(), names);
  }

  void write_data(const std::filesystem::path& folder) const override {
    const std::vector<LabRun>& runs = lab_runs(table_);
    tutorial::Plot plot{table_.stem,
                        table_.scene + ": " + followed_name(table_) + ", 60 Hz" +
                            (log_plot(table_) ? " (below 1 µm drawn at 1 µm)" : ""),
                        "t (s)", followed_name(table_), {}, {},
                        log_plot(table_) ? "bottom right" : "center right", log_plot(table_)};
    tutorial::Plot energy{table_.stem + "_energy", table_.scene + ": mechanical energy, 60 Hz",
                          "t (s)", "E (J)", {}, {}, "bottom left"};
    for (std::size_t c = 0; c < runs.size(); ++c) {
      const Contender& who = contenders()[c];
      plot.series.push_back({who.name, who.colour, who.name == "islands"});
      energy.series.push_back({who.name, who.colour, who.name == "islands"});
    }
    for (int k = 0; k < lab_steps; ++k) {
      std::vector<double> row{(k + 1) * scene_.step.dt}, e_row = row;
      for (const LabRun& run : runs) {
        const bool have = k < static_cast<int>(run.samples.size());
        const double value = have ? followed(table_, run.samples[k]) : std::numeric_limits<double>::quiet_NaN();
        row.push_back(log_plot(table_) ? std::max(value, micrometre(table_)) : value);
        e_row.push_back(have ? run.samples[k].energy : std::numeric_limits<double>::quiet_NaN());
      }
      plot.rows.push_back(row);
      energy.rows.push_back(e_row);
    }
    tutorial::write_plot(folder, plot);
    if (!scene_.joints.empty()) tutorial::write_plot(folder, energy);
  }

 private:
  TableScene table_;
  lamina::Scene scene_;
  long step_ = 0;  // k: the frame shows the state at t = k Δt, poses[k] of each run
};

}  // namespace

tutorial::SceneFactory overlay_scene(const TableScene& scene) {
  return [scene](const tutorial::Options&) { return std::make_unique<Overlay>(scene); };
}

}  // namespace lamina::ch6
