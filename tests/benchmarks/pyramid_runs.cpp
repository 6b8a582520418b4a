#include "benchmarks/pyramid_runs.h"

#include <time.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "constraints/pgs_solver.h"
#include "app/reference/box2d_scene.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina {
namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Times `timed_steps` calls of step(): mean CPU and wall-clock milliseconds per step.
void time_steps(const std::function<void()>& step, PyramidRun& run) {
  const double cpu_start = cpu_seconds();
  const auto wall_start = std::chrono::steady_clock::now();
  for (int i = 0; i < timed_steps; ++i) step();
  const std::chrono::duration<double, std::milli> wall =
      std::chrono::steady_clock::now() - wall_start;
  run.ms_per_step = 1e3 * (cpu_seconds() - cpu_start) / timed_steps;
  run.wall_ms_per_step = wall.count() / timed_steps;
}

// The apex (the last body, the top box or hexagon) and the largest sideways move of any dynamic
// body.
void measure_standing(const Scene& scene, const Positions& start, const Positions& end,
                      PyramidRun& run) {
  const size_t apex = scene.bodies.size() - 1;
  run.apex_shift = std::hypot(end[apex][0] - start[apex][0], end[apex][1] - start[apex][1]);
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].is_static) continue;
    ++run.bodies;
    run.largest_sideways = std::max(run.largest_sideways, std::abs(end[i][0] - start[i][0]));
  }
}

// The sweeps after which a recorded residual first is ≤ target; max_sweeps if never.
double sweeps_to(const std::vector<double>& residuals, double target, int max_sweeps) {
  for (size_t k = 0; k < residuals.size(); ++k) {
    if (residuals[k] <= target) return static_cast<double>(k + 1);
  }
  return max_sweeps;
}

}  // namespace

PyramidRun measure_pyramid_run(const Scene& scene, const std::function<void()>& step,
                               const std::function<Positions()>& where,
                               const std::function<void(PyramidRun&)>& count_rows) {
  PyramidRun run;
  const Positions start = where();
  step();
  time_steps(step, run);
  count_rows(run);
  for (int i = 1 + timed_steps; i < standing_steps; ++i) step();
  measure_standing(scene, start, where(), run);
  return run;
}

std::string shape_name(PyramidShape shape) {
  return shape == PyramidShape::boxes ? "boxes" : "hexagons";
}

Scene pyramid_of(PyramidShape shape, int base) {
  if (shape == PyramidShape::boxes) return pyramid_scene(base);
  return builtin_scene("hexagon-pyramid:" + std::to_string(base));
}

double PyramidRun::us_per_row_sweep() const {
  const double row_sweeps = static_cast<double>(velocity_rows) * velocity_iterations +
                            static_cast<double>(position_rows) * position_iterations;
  return 1e3 * ms_per_step / row_sweeps;
}

PyramidRun run_lamina_pyramid(PyramidShape shape, int base, int iterations,
                              const std::string& solver, int threads) {
  Scene scene = pyramid_of(shape, base);
  scene.solver = solver;
  WorldSettings settings = world_settings(scene);
  settings.step.iterations = iterations;
  settings.threads = threads;
  World world = build_world(scene, settings);
  const auto where = [&] {
    Positions p;
    for (const RigidBody& body : world.bodies()) p.push_back({body.x.x(), body.x.y()});
    return p;
  };
  const auto count_rows = [&](PyramidRun& run) {
    run.phases = world.step_times_after_first();  // called right after the timed steps
    for (const ContactPair& pair : world.contact_pairs()) {
      run.contact_points += pair.count;
      run.velocity_rows += pair.rows.count;  // its contact and friction rows (the row map)
    }
    run.position_rows = run.contact_points;  // split impulse: one row per contact
    run.velocity_iterations = settings.step.iterations;
    run.position_iterations = settings.position_iterations;
  };
  return measure_pyramid_run(scene, [&] { world.step(); }, where, count_rows);
}

PyramidRun run_box2d_pyramid(PyramidShape shape, int base) {
  const Scene scene = pyramid_of(shape, base);
  Box2dScene box2d = make_box2d_scene(scene);
  const auto where = [&] {
    Positions p;
    for (const b2Body* body : box2d.bodies) {
      p.push_back({body->GetPosition().x, body->GetPosition().y});
    }
    return p;
  };
  const auto count_rows = [&](PyramidRun& run) {
    for (b2Contact* c = box2d.world->GetContactList(); c != nullptr; c = c->GetNext()) {
      if (c->IsTouching()) run.contact_points += c->GetManifold()->pointCount;
    }
    run.velocity_rows = 2 * run.contact_points;  // a normal and a friction row per point
    run.position_rows = run.contact_points;      // the position pass corrects along the normal
    run.velocity_iterations = box2d.settings.velocity_iterations;
    run.position_iterations = box2d.settings.position_iterations;
  };
  return measure_pyramid_run(scene, [&] { box2d.step(); }, where, count_rows);
}

WarmStartRun measure_warm_start(int base, int first_step, int steps,
                                const std::vector<double>& reductions, int max_sweeps) {
  WarmStartRun run{base,       first_step, steps, max_sweeps,
                   reductions, std::vector<double>(reductions.size(), 0.0),
                   std::vector<double>(reductions.size(), 0.0)};
  Scene scene = pyramid_scene(base);
  scene.solver = "pgs";
  World world = build_world(scene, world_settings(scene));
  for (int i = 0; i < first_step; ++i) world.step();
  for (int k = 0; k < steps; ++k) {
    WorldReport report;
    world.step(report);
    const Mlcp& mlcp = report.velocity.mlcp;
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(mlcp.row_count());
    const double at_zero = mlcp.residual(zero.data());
    const double smallest = *std::min_element(reductions.begin(), reductions.end());
    // every sweep's residual, until the smallest one asked for
    const SweepSettings record{max_sweeps, smallest * at_zero, true};
    const std::vector<double> warm = solve_pgs(mlcp, report.velocity.lambda_exp, record).residuals;
    const std::vector<double> cold = solve_pgs(mlcp, zero, record).residuals;
    for (size_t r = 0; r < reductions.size(); ++r) {
      run.warm_sweeps[r] += sweeps_to(warm, reductions[r] * at_zero, max_sweeps) / steps;
      run.cold_sweeps[r] += sweeps_to(cold, reductions[r] * at_zero, max_sweeps) / steps;
    }
    run.warm_residual_10 += warm[std::min<size_t>(9, warm.size() - 1)] / at_zero / steps;
    run.cold_residual_10 += cold[std::min<size_t>(9, cold.size() - 1)] / at_zero / steps;
  }
  return run;
}

}  // namespace lamina
