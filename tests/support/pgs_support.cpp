#include "support/pgs_support.h"

#include <cstring>
#include <utility>

#include "scene/scene_world.h"

namespace lamina {

std::vector<unsigned char> bytes_of(const double* values, std::size_t count) {
  std::vector<unsigned char> bytes(count * sizeof(double));
  if (count > 0) std::memcpy(bytes.data(), values, bytes.size());
  return bytes;
}

WorldReport report_after(int steps, Scene scene) {
  scene.solver = "pgs";
  World world = build_world(scene, world_settings(scene));
  for (int k = 0; k < steps; ++k) world.step();
  WorldReport report;
  world.step(report);
  return report;
}

StepReport mlcp_after(int steps, Scene scene) {
  return report_after(steps, std::move(scene)).velocity;
}

std::vector<unsigned char> solved(PgsSolver& solver, const StepReport& step, int sweeps,
                                  Pitfalls pitfalls) {
  std::vector<double> lambda(step.lambda_exp.data(),
                             step.lambda_exp.data() + step.lambda_exp.size());
  SweepResult result;
  solver.solve(step.mlcp, lambda.data(), {sweeps, 0.0, false}, result, pitfalls);
  return bytes_of(lambda.data(), lambda.size());
}

}  // namespace lamina
