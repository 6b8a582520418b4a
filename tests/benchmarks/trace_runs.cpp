#include "benchmarks/trace_runs.h"

#include <time.h>

#include <filesystem>

#include "benchmarks/pyramid_runs.h"
#include "scene/scene_world.h"
#include "trace/trace.h"
#include "trace/trace_writer.h"

namespace lamina {
namespace {

double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace

TraceRun run_traced_pyramid(int base, const std::string& solver, int steps) {
  Scene scene = pyramid_of(PyramidShape::boxes, base);
  scene.solver = solver;
  World world = build_world(scene, world_settings(scene));
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("lamina_trace_benchmark_" + solver + ".jsonl");
  TraceRun run;
  {
    TraceWriter writer(file);
    TraceStep record;  // refilled step after step, as lamina run does
    for (int k = 0; k < steps; ++k) {
      const double start = cpu_ms();
      world.step();
      const double stepped = cpu_ms();
      trace_step(scene, world, k, record);
      writer.write(record);
      run.physics_ms += stepped - start;
      run.trace_ms += cpu_ms() - stepped;
    }
    const double start = cpu_ms();
    writer.finish();
    run.trace_ms += cpu_ms() - start;
  }
  run.physics_ms /= steps;
  run.trace_ms /= steps;
  run.megabytes = static_cast<double>(std::filesystem::file_size(file)) / 1e6;
  std::filesystem::remove(file);
  return run;
}

}  // namespace lamina
