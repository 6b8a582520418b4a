// Issue 8's benchmarks: Lamina beside Box2D 2.4.1 on pyramids of boxes (pyramid_runs.h), then the
// tables of docs/performance.md (report.h).
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
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmarks/report.h"

using namespace lamina;

namespace {

Measurements measurements;  // every repetition's numbers, for the tables at the end

void record(benchmark::State& state, const RunKey& key, const PyramidRun& run) {
  // the manual time is the step's: Google Benchmark's "Time" column is ms per step
  state.SetIterationTime(run.ms_per_step / 1e3);
  state.counters["boxes"] = run.boxes;
  state.counters["contact_points"] = run.contact_points;
  state.counters["standing"] = run.standing() ? 1 : 0;
  measurements.runs[key].push_back(run);
}

void lamina_pyramid(benchmark::State& state) {
  const int base = static_cast<int>(state.range(0));
  const int iterations = static_cast<int>(state.range(1));
  for (auto _ : state) {
    record(state, {"Lamina", base, iterations}, run_lamina_pyramid(base, iterations));
  }
}

void box2d_pyramid(benchmark::State& state) {
  const int base = static_cast<int>(state.range(0));
  for (auto _ : state) record(state, {"Box2D", base, 8}, run_box2d_pyramid(base));
}

// Base 20 and 40 at the recommended 10 sweeps and at Box2D's 8; the scaling bases at 8.
BENCHMARK(lamina_pyramid)
    ->ArgNames({"base", "iterations"})
    ->ArgsProduct({{20, 40}, {10, 8}})
    ->Args({10, 8})
    ->Args({80, 8})
    ->UseManualTime()
    ->Iterations(1)
    ->Repetitions(7)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(box2d_pyramid)
    ->ArgName("base")
    ->Arg(10)
    ->Arg(20)
    ->Arg(40)
    ->Arg(80)
    ->UseManualTime()
    ->Iterations(1)
    ->Repetitions(7)
    ->Unit(benchmark::kMillisecond);

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
    for (const char* name : {"machine", "pyramids", "scaling", "warm_start"}) {
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
