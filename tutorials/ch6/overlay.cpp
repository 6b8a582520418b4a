#include "ch6/overlay.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "app/harness/format.h"
#include "app/harness/plot.h"
#include "app/views/contact/stepped_world.h"
#include "app/views/contact/world_view.h"
#include "app/views/contact/world_explanation.h"
#include "beyond/methods.h"
#include "language/language.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina::ch6 {
namespace {

using tutorial::fixed;

constexpr int every = 20;  // steps between frames: 31 frames show t = 0 … 10 s

render::Body body_at(const BodyDescription& d, const Pose& pose, render::Colour fill) {
  render::Body b;
  view::set_outline(b, place_shape(d).shape);
  b.centre = pose.head<2>();
  b.angle = pose.z();
  b.fill = fill;
  b.fixed = d.is_static;
  return b;
}

class Overlay : public tutorial::Scene {
 public:
  explicit Overlay(Comparison c) : c_(std::move(c)) {}

  tutorial::SceneInfo info() const override {
    return {c_.stem, c_.scene.step.dt, lab_steps / every + 1, every, view()};
  }

  void step() override { ++step_; }

  void draw(render::Frame& frame) const override {
    const std::vector<LabRun>& runs = c_.runs();
    frame.caption = c_.caption;
    for (std::size_t b = 0; b < c_.scene.bodies.size(); ++b) {
      if (c_.scene.bodies[b].is_static) {
        frame.bodies.push_back(body_at(c_.scene.bodies[b], runs[0].poses[0][b], render::palette::grid));
      }
    }
    render::Panel panel;
    panel.corner = render::Corner::top_left;
    panel.title = fill(tr("largest so far: {0}"), {c_.measure});
    std::size_t width = 0;
    // in characters: a name in Korean has three bytes a syllable
    const auto characters = [](const std::string& s) {
      std::size_t n = 0;
      for (const char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
      return n;
    };
    for (const Contender& who : c_.who) width = std::max(width, characters(who.name));
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const LabRun& run = runs[r];
      const Contender& who = c_.who[r];
      // the state at t = step_ Δt; a run that diverged stays drawn where it was last finite
      const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(step_), run.poses.size() - 1);
      for (std::size_t b = 0; b < c_.scene.bodies.size(); ++b) {
        if (c_.scene.bodies[b].is_static) continue;
        frame.bodies.push_back(body_at(c_.scene.bodies[b], run.poses[k][b],
                                       render::with_alpha(tint(who.colour, 0.7), 110)));
      }
      frame.legend.push_back({render::LegendEntry::Sample::swatch, who.colour, who.name});
      double most = 0.0;  // over the samples up to the state shown
      for (std::size_t i = 0; i < k; ++i) most = std::max(most, c_.followed(run.samples[i]));
      std::string line = who.name + std::string(width + 2 - characters(who.name), ' ');
      const bool gone = run.diverged && static_cast<std::size_t>(step_) >= run.poses.size();
      panel.lines.push_back(line + (gone ? std::string(tr("diverged")) : fixed(most, 3)));
    }
    frame.panels.push_back(panel);
    frame.legend_corner = render::Corner::top_right;
  }

  tutorial::Explanation explain() const override {
    // What one of the runs solved in this step: the World stepped again to it (the runs keep
    // poses, not reports).
    view::SteppedWorld world(build_world(c_.explained, world_settings(c_.explained)));
    for (long k = 0; k <= step_; ++k) world.step();
    std::vector<std::string> names;
    for (const BodyDescription& b : c_.scene.bodies) names.push_back(b.name);
    return view::explain_world_step(world.world(), world.report(), names);
  }

  void write_data(const std::filesystem::path& folder) const override {
    const std::vector<LabRun>& runs = c_.runs();
    tutorial::Plot plot{c_.stem,
                        scene_title(c_.scene.name) + ": " + c_.measure + ", 60 Hz" +
                            (c_.log_plot ? tr(" (below 1 µm drawn at 1 µm)") : ""),
                        "t (s)", c_.measure, {}, {}, c_.legend, c_.log_plot};
    tutorial::Plot energy{c_.stem + "_energy",
                          fill(tr("{0}: mechanical energy, 60 Hz"), {scene_title(c_.scene.name)}),
                          "t (s)", "E (J)", {}, {}, "bottom left"};
    for (const Contender& who : c_.who) {
      plot.series.push_back({who.name, who.colour, who.name == "islands"});
      energy.series.push_back({who.name, who.colour, who.name == "islands"});
    }
    for (int k = 0; k < lab_steps; ++k) {
      std::vector<double> row{(k + 1) * c_.scene.step.dt}, e_row = row;
      for (const LabRun& run : runs) {
        const bool have = k < static_cast<int>(run.samples.size());
        const double value = have ? c_.followed(run.samples[k]) : std::numeric_limits<double>::quiet_NaN();
        row.push_back(c_.log_plot ? std::max(value, c_.floor) : value);
        e_row.push_back(have ? run.samples[k].energy : std::numeric_limits<double>::quiet_NaN());
      }
      plot.rows.push_back(row);
      energy.rows.push_back(e_row);
    }
    tutorial::write_plot(folder, plot);
    if (!c_.scene.joints.empty()) tutorial::write_plot(folder, energy);
  }

 private:
  // The comparison's region, grown upwards to hold every moving body of every run at every step
  // (a body thrown above it would be drawn over the caption), with 0.3 m to spare, and sideways
  // by as much as half its width each way; a body sliding or falling further leaves the frame.
  render::Rect view() const {
    const render::Rect least = c_.view;
    render::Rect r = least;
    std::vector<Shape> shapes;
    for (const BodyDescription& d : c_.scene.bodies) shapes.push_back(place_shape(d).shape);
    for (const LabRun& run : c_.runs()) {
      for (const std::vector<Pose>& poses : run.poses) {
        for (std::size_t b = 0; b < poses.size(); ++b) {
          const BodyDescription& d = c_.scene.bodies[b];
          if (d.is_static) continue;
          const double reach = 0.3 + outer_radius(shapes[b]);
          r.min.x() = std::min(r.min.x(), poses[b].x() - reach);
          r.max = r.max.cwiseMax(poses[b].head<2>() + Vec2(reach, reach));
        }
      }
    }
    const double width = least.size().x();
    r.min.x() = std::max(r.min.x(), least.min.x() - 0.5 * width);
    r.max.x() = std::min(r.max.x(), least.max.x() + 0.5 * width);
    r.max.y() += c_.headroom;
    return r;
  }

  Comparison c_;
  long step_ = 0;  // k: the frame shows the state at t = k Δt, poses[k] of each run
};

}  // namespace

tutorial::SceneFactory overlay_scene(std::function<Comparison()> make) {
  return [make](const tutorial::Options&) { return std::make_unique<Overlay>(make()); };
}

Comparison table_comparison(const TableScene& s) {
  Comparison c;
  c.stem = s.stem;
  c.caption = fill(tr("Chapter 6 · {0} by Box2D 2.4.1 and each of Lamina's methods, overlaid"),
                   {scene_title(s.scene)});
  c.scene = builtin_scene(s.scene);
  c.explained = c.scene;
  c.explained.solver = default_method;  // Lamina's own
  c.view = s.view;
  c.who = contenders();
  c.runs = [s]() -> const std::vector<LabRun>& { return lab_runs(s); };
  const bool heavy = s.scene.rfind("heavy-on-light", 0) == 0;
  const bool chain = s.scene == "ball-and-chain:100";
  // the chain's ball swings up to the pin's height on both sides: room above it for the numbers
  if (chain) c.headroom = 3.0;
  c.measure = heavy ? tr("deepest overlap (mm)")
              : chain ? tr("pin to ball past its rest length (%)")
              : s.scene == "vertical-stack:20" ? tr("top box moved (m)") : tr("apex moved (m)");
  c.followed = heavy ? [](const LabSample& x) { return 1000.0 * x.overlap; }
               : chain ? [](const LabSample& x) { return 100.0 * x.stretch; }
               : [](const LabSample& x) { return x.top; };
  // A logarithmic plot shows a holding run (round-off) beside a falling one (metres); the
  // chain's stretch, which may be negative, stays linear.
  c.log_plot = !chain;
  c.floor = heavy ? 1e-3 : 1e-6;  // 1 µm
  c.legend = chain ? "center right" : "bottom right";
  return c;
}

Comparison pitfall_comparison(const PitfallDemo& demo) {
  Comparison c;
  c.stem = "pitfall_" + demo.stem;
  c.scene = demo_scene(demo);
  c.explained = c.scene;
  c.explained.step.pitfalls.add(demo.pitfall);  // what the mistake computes
  c.caption = fill(tr("Chapter 6 · pitfall {0} on {1}: {2} as it is, and with the mistake"),
                   {pitfall_name(demo.pitfall), scene_title(c.scene.name), demo.method});
  c.view = demo.view;
  c.who = {{fill(tr("{0} as it is"), {demo.method}), render::palette::bluish_green},
           {fill(tr("with {0}"), {pitfall_name(demo.pitfall)}), render::palette::vermillion}};
  c.runs = [demo]() -> const std::vector<LabRun>& { return pitfall_runs(demo); };
  c.measure = shown(demo.measure);
  c.followed = [](const LabSample& x) { return x.top; };
  c.log_plot = true;
  c.floor = 1e-6;
  c.legend = "bottom right";
  return c;
}

}  // namespace lamina::ch6
