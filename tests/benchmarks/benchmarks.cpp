// Issue 8's benchmarks: Lamina beside Box2D 2.4.1 on pyramids of boxes (pyramid_runs.h), and
// issue 20's on pyramids of hexagons; issue 19's peers, two threads and traces (trace_runs.h);
// then the tables of docs/performance.md (report.h).
//
//   lamina_benchmarks [--report=FOLDER] [--doc=FILE.md] [Google Benchmark flags]
//
// Each benchmark repetition builds a fresh pyramid, steps it for 10 s of simulated time and
// reports the mean CPU time per step over the 500 steps after the first (its "Time"); the tables
// take the median and the fastest of the 7 repetitions, run in random order among all
// benchmarks. --report writes the tables as Markdown and CSV into FOLDER; --doc replaces the
// generated tables in a Markdown file (between its markers).
#include <benchmark/benchmark.h>

#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmarks/cross_core.h"
#include "benchmarks/report.h"
#include "contact/world.h"
#ifdef LAMINA_HAVE_BOX2D_V3
#include "benchmarks/box2d_v3_runs.h"
#endif

using namespace lamina;

namespace {

Measurements measurements;  // every repetition's numbers, for the tables at the end

void record(benchmark::State& state, const RunKey& key, const PyramidRun& run) {
  // the manual time is the step's: Google Benchmark's "Time" column is ms per step
  state.SetIterationTime(run.ms_per_step / 1e3);
  state.counters["bodies"] = run.bodies;
  state.counters["contact_points"] = run.contact_points;
  state.counters["standing"] = run.standing() ? 1 : 0;
  measurements.runs[key].push_back(run);
}

// Lamina on a pyramid of that shape: range(0) bodies in the base, range(1) sweeps per step.
void lamina_run(benchmark::State& state, PyramidShape shape) {
  const int base = static_cast<int>(state.range(0));
  const int iterations = static_cast<int>(state.range(1));
  for (auto _ : state) {
    record(state, {"Lamina", base, iterations, shape}, run_lamina_pyramid(shape, base, iterations));
  }
}

// Box2D on a pyramid of that shape: range(0) bodies in the base, 8 / 3 iterations.
void box2d_run(benchmark::State& state, PyramidShape shape) {
  const int base = static_cast<int>(state.range(0));
  for (auto _ : state) record(state, {"Box2D", base, 8, shape}, run_box2d_pyramid(shape, base));
}

// Lamina's default method, `islands`, at its default sweeps: range(0) bodies in the base.
void lamina_islands_pyramid(benchmark::State& state) {
  const int base = static_cast<int>(state.range(0));
  const int iterations = WorldSettings().step.iterations;
  for (auto _ : state) {
    record(state, {"Lamina islands", base, iterations},
           run_lamina_pyramid(PyramidShape::boxes, base, iterations, "islands"));
  }
}

// Lamina's `pgs` at Box2D's sweeps on two threads (issue 19): range(0) bodies in the base. Each
// repetition runs the pyramid on one thread and then on two, right after measuring the round
// trip of a cache line between the cores and how fast each core runs one thread of pyramid:20
// (cross_core.h): the speed-up is each pair's, both sides of it on the machine as it was then.
void lamina_pyramid_two_threads(benchmark::State& state) {
  const int base = static_cast<int>(state.range(0));
  for (auto _ : state) {
    ThreadPair pair;
    pair.round_trip_ns = cross_core_round_trip_ns();
    pair.first_cpu_ratio = first_cpu_time_ratio(
        [] { return run_lamina_pyramid(PyramidShape::boxes, 20, 8, "pgs", 1).ms_per_step; });
    pair.one = run_lamina_pyramid(PyramidShape::boxes, base, 8, "pgs", 1);
    pair.two = run_lamina_pyramid(PyramidShape::boxes, base, 8, "pgs", 2);
    record(state, {"Lamina 2 threads", base, 8}, pair.two);
    measurements.thread_pairs[base].push_back(pair);
  }
}

// Issue 19's trace bar: pyramid:20 traced for 10 s by `solver` (trace_runs.h); the manual time
// is the trace's CPU time per step.
void lamina_trace(benchmark::State& state, const std::string& solver) {
  for (auto _ : state) {
    const TraceRun run = run_traced_pyramid(20, solver, standing_steps);
    state.SetIterationTime(run.trace_ms / 1e3);
    state.counters["physics_ms"] = run.physics_ms;
    measurements.traces[solver].push_back(run);
  }
}

void lamina_pyramid(benchmark::State& state) { lamina_run(state, PyramidShape::boxes); }
void box2d_pyramid(benchmark::State& state) { box2d_run(state, PyramidShape::boxes); }
void lamina_hexagon_pyramid(benchmark::State& state) { lamina_run(state, PyramidShape::hexagons); }
void box2d_hexagon_pyramid(benchmark::State& state) { box2d_run(state, PyramidShape::hexagons); }

// Every benchmark: one pyramid run per repetition, 7 repetitions, its "Time" the run's CPU ms per
// step (manual time).
benchmark::internal::Benchmark* per_step(benchmark::internal::Benchmark* b) {
  return b->UseManualTime()->Iterations(1)->Repetitions(7)->Unit(benchmark::kMillisecond);
}

// A benchmark over pyramid bases: range(0) is the base.
benchmark::internal::Benchmark* over_bases(benchmark::internal::Benchmark* b,
                                           std::initializer_list<int> bases) {
  b->ArgName("base");
  for (const int base : bases) b->Arg(base);
  return per_step(b);
}

#ifdef LAMINA_HAVE_BOX2D_V3
void box2d_v3_pyramid(benchmark::State& state) {
  const int base = static_cast<int>(state.range(0));
  for (auto _ : state) {
    record(state, {"Box2D v3", base, box2d_v3_substeps}, run_box2d_v3_pyramid(base));
  }
}
#endif

// Base 20 and 40 at the recommended 10 sweeps and at Box2D's 8; the scaling bases at 8.
const auto* const lamina_boxes = per_step(
    benchmark::RegisterBenchmark("lamina_pyramid", lamina_pyramid)
        ->ArgNames({"base", "iterations"})
        ->ArgsProduct({{20, 40}, {10, 8}})
        ->Args({10, 8})
        ->Args({80, 8}));
const auto* const box2d_boxes =
    over_bases(benchmark::RegisterBenchmark("box2d_pyramid", box2d_pyramid), {10, 20, 40, 80});
// Issue 19's peers: Lamina's default method, and Box2D v3 when it is built in.
const auto* const islands_boxes = over_bases(
    benchmark::RegisterBenchmark("lamina_islands_pyramid", lamina_islands_pyramid), {20, 40, 80});
const auto* const two_threads_boxes = over_bases(
    benchmark::RegisterBenchmark("lamina_pyramid_two_threads", lamina_pyramid_two_threads),
    {20, 40, 80});
#ifdef LAMINA_HAVE_BOX2D_V3
const auto* const v3_boxes =
    over_bases(benchmark::RegisterBenchmark("box2d_v3_pyramid", box2d_v3_pyramid), {20, 40, 80});
#endif
// The trace's cost by `pgs` and by the default method.
const auto* const traces_pgs =
    per_step(benchmark::RegisterBenchmark("lamina_trace/pgs", lamina_trace, std::string("pgs")));
const auto* const traces_islands = per_step(
    benchmark::RegisterBenchmark("lamina_trace/islands", lamina_trace, std::string("islands")));
// Hexagon pyramids at Box2D's sweeps, both engines, bases 10, 20 and 40.
const auto* const lamina_hexagons = per_step(
    benchmark::RegisterBenchmark("lamina_hexagon_pyramid", lamina_hexagon_pyramid)
        ->ArgNames({"base", "iterations"})
        ->ArgsProduct({{10, 20, 40}, {8}}));
const auto* const box2d_hexagons = over_bases(
    benchmark::RegisterBenchmark("box2d_hexagon_pyramid", box2d_hexagon_pyramid), {10, 20, 40});

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c, tasks;
  in >> a >> b >> c >> tasks;
  return a + " " + b + " " + c + "; " + tasks;
}

// Takes --report=FOLDER and --doc=FILE out of the arguments, leaving Google Benchmark's.
std::string take_option(int& argc, char** argv, const char* name) {
  const size_t length = std::strlen(name);
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], name, length) != 0) continue;
    const std::string value = argv[i] + length;
    for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
    --argc;
    if (value.empty()) throw std::invalid_argument(std::string(name) + " needs a value");
    return value;
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string report = take_option(argc, argv, "--report=");
    const std::string doc = take_option(argc, argv, "--doc=");
    // Repetitions of different benchmarks interleaved at random, so that a busy spell on the
    // machine does not land on one engine only (a later flag on the command line overrides).
    std::vector<char*> args(argv, argv + argc);
    std::string interleave = "--benchmark_enable_random_interleaving=true";
    args.insert(args.begin() + 1, interleave.data());
    int count = static_cast<int>(args.size());
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
    measurements.load_before = load_average();
    benchmark::RunSpecifiedBenchmarks();
    // the resting pyramids, after 100 steps to settle
    measurements.warm_starts.push_back(measure_warm_start(20, 100, 20, {0.1, 0.01}, 5000));
    measurements.warm_starts.push_back(measure_warm_start(40, 100, 3, {0.1, 0.01}, 5000));
    measurements.load_after = load_average();
    const Tables tables = make_tables(measurements);
    for (const char* name :
         {"machine", "pyramids", "peers", "threads", "profile", "scaling", "warm_start", "hexagons",
          "traces"}) {
      std::cout << "\n" << tables.at(name);
    }
    if (!report.empty()) write_tables(tables, report);
    if (!doc.empty()) update_doc(tables, doc);
    benchmark::Shutdown();
  } catch (const std::exception& error) {
    std::cerr << "lamina_benchmarks: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
