#include "ch6/sweeps.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "app/harness/format.h"
#include "app/harness/plot.h"
#include "app/views/contact/stepped_world.h"
#include "app/views/contact/world_explanation.h"
#include "app/views/contact/world_view.h"
#include "beyond/block_method.h"
#include "ch6/lab.h"
#include "constraints/exact_mlcp.h"
#include "constraints/pgs_solver.h"
#include "language/language.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina::ch6 {
namespace {

using tutorial::fixed;
using tutorial::scientific;

constexpr int most_sweeps = 1000;
// The step whose MLCP lambda_error.png plots: step 60, from t = 1 s (both scenes resting).
constexpr long plotted_step = 60;

// max_i |λ_i − λ*_i| after each of `most_sweeps` sweeps from λ = 0 (a cold start, as without
// the cache: a warm start from the last step's exact λ is already within round-off), by PGS or
// by the block solver, λ* being Lemke's exact λ of the same MLCP; in N. The frames show the
// error after 1 … 1000 sweeps.
struct SweepErrors {
  std::vector<double> pgs, block;
  bool exact = false;  // Lemke found λ*
};

SweepErrors sweep_errors(const StepReport& step) {
  SweepErrors out;
  const ExactSolution exact = solve_mlcp_exactly(step.mlcp);
  if (exact.status != LemkeStatus::solved) return out;
  out.exact = true;
  const auto error = [&](const double* lambda) {
    double e = 0.0;
    for (Eigen::Index i = 0; i < exact.lambda.size(); ++i) e = std::max(e, std::abs(lambda[i] - exact.lambda[i]));
    return e;
  };
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(exact.lambda.size());
  PgsSolver pgs;
  for (int k = 0; k < most_sweeps; ++k) {
    SweepResult one;
    pgs.solve(step.mlcp, lambda.data(), {1, 0.0, false}, one);
    out.pgs.push_back(error(lambda.data()));
  }
  lambda.setZero();
  block_sweeps(step.mlcp, lambda.data(), most_sweeps,
               [&](int, const double* l) { out.block.push_back(error(l)); });
  return out;
}

World world_of(const std::string& name) {
  Scene scene = builtin_scene(name);
  scene.solver = "islands";
  return build_world(scene, world_settings(scene));
}

// The sweep errors of a scene's plotted step, by a run of its own.
SweepErrors errors_at_plotted_step(const std::string& name) {
  view::SteppedWorld world(world_of(name));
  while (world.step_index() < plotted_step) world.step();
  return sweep_errors(world.report().velocity);
}

// The frames show heavy-on-light:1000 step after step with the sweep errors of each step; the
// plot (write_data) takes the errors of its step 60 from the frames' run, which gets there at
// the default 4 frames 20 steps apart (a run of its own only when --frames or --every stop
// the frames before it).
class Sweeps : public tutorial::Scene {
 public:
  Sweeps() : world_(world_of("heavy-on-light:1000")) { world_.step(); }

  tutorial::SceneInfo info() const override {
    return {"lambda_error", world_.world().settings().step.dt, 4, 20, {Vec2(-4.0, -0.4), Vec2(4.0, 3.6)}};
  }
  void step() override {
    world_.step();
    if (world_.step_index() == plotted_step) plotted_ = sweep_errors(world_.report().velocity);
  }

  void draw(render::Frame& frame) const override {
    frame = view::world_frame(world_.world(), world_.bodies_at_t());
    frame.caption = fill(tr("Chapter 6 · one step's λ after n sweeps, against the exact λ* (Lemke) · {0}"),
                         {scene_title("heavy-on-light:1000")});
    frame.force_scale = 0.8 / 9800.0;  // the heavy box's weight, 9800 N, drawn 0.8 m long
    // the last step's errors: the plotted step's as kept, another's computed for its frame
    const bool plotted = plotted_ && world_.step_index() == plotted_step;
    const SweepErrors e = plotted ? *plotted_ : sweep_errors(world_.report().velocity);
    render::Panel p;
    p.corner = render::Corner::top_left;
    p.title = tr("max |λ − λ*| after n sweeps from λ = 0 (N)");
    p.lines.push_back("    n   pgs        block");
    if (e.exact) {
      for (const int n : {1, 3, 10, 30, 100, 300, 1000}) {
        std::string count = std::to_string(n);
        count.insert(0, 5 - count.size(), ' ');
        p.lines.push_back(count + "   " + scientific(e.pgs[n - 1]) + "    " + scientific(e.block[n - 1]));
      }
    } else {
      p.lines.push_back(tr("  (Lemke found no λ* for this step)"));
    }
    frame.panels.push_back(p);
    frame.legend_corner = render::Corner::top_right;
    const std::vector<RigidBody>& at_t = world_.bodies_at_t();
    frame.labels.push_back({at_t[1].x.head<2>() + Vec2(0.65, 0.0), tr("light: 1 kg"), render::palette::ink});
    frame.labels.push_back({at_t[2].x.head<2>() + Vec2(0.65, 0.0), tr("heavy: 1000 kg"), render::palette::ink});
  }

  tutorial::Explanation explain() const override {
    return view::explain_world_step(world_.world(), world_.report(), {tr("ground"), tr("light"), tr("heavy")});
  }

  void write_data(const std::filesystem::path& folder) const override {
    tutorial::Plot plot{"lambda_error",
                        tr("One resting step's MLCP: max |λ − λ*| after n sweeps from λ = 0"),
                        tr("sweeps n"), "max |λ − λ*| (N)", {}, {}, "bottom left", true};
    const std::vector<SweepErrors> errors{
        plotted_ ? *plotted_ : errors_at_plotted_step("heavy-on-light:1000"),
        errors_at_plotted_step("vertical-stack:20")};
    for (const std::string name : {"heavy-on-light:1000", "vertical-stack:20"}) {
      const bool dashed = name == "vertical-stack:20";
      plot.series.push_back({"pgs, " + scene_title(name), render::palette::orange, dashed});
      plot.series.push_back({"block, " + scene_title(name), render::palette::reddish_purple, dashed});
    }
    for (int n = 1; n <= most_sweeps; ++n) {
      std::vector<double> row{static_cast<double>(n)};
      for (const SweepErrors& e : errors) {
        // a log axis has no 0: an error of exactly 0 is drawn at 1e-16 N, round-off's floor
        row.push_back(std::max(e.pgs.empty() ? NAN : e.pgs[n - 1], 1e-16));
        row.push_back(std::max(e.block.empty() ? NAN : e.block[n - 1], 1e-16));
      }
      plot.rows.push_back(row);
    }
    tutorial::write_plot(folder, plot);
  }

 private:
  view::SteppedWorld world_;
  std::optional<SweepErrors> plotted_;  // of the plotted step, once the frames' run took it
};

}  // namespace

tutorial::SceneFactory sweeps_scene() {
  return [](const tutorial::Options&) { return std::make_unique<Sweeps>(); };
}

}  // namespace lamina::ch6
