// The benchmarks' tables (Markdown for docs/performance.md, CSV for the plot and for reading
// back), made from the runs; and the writing of them.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "benchmarks/pyramid_runs.h"
#include "benchmarks/trace_runs.h"

namespace lamina {

// Which engine at which pyramid and sweeps; Box2D 2.4.1's sweeps are always 8 / 3, Box2D v3's
// "sweeps" are its substeps.
struct RunKey {
  std::string engine;                        // "Lamina" (pgs), "Lamina 2 threads" (pgs),
                                             // "Lamina islands", "Box2D" (2.4.1) or "Box2D v3"
  int base = 0;                              // bodies in the pyramid's base
  int iterations = 0;                        // velocity sweeps per step
  PyramidShape shape = PyramidShape::boxes;  // what the pyramid is built of

  bool operator<(const RunKey& o) const;
};

// One repetition of the two-thread benchmark: the same pyramid on one thread, then on two.
struct ThreadPair {
  std::optional<double> round_trip_ns;    // a cache line between the cores and back, just before
  std::optional<double> first_cpu_ratio;  // one thread's pyramid:20, first CPU ÷ second, before
  PyramidRun one;                         // on one thread
  PyramidRun two;                         // on two threads
};

struct Measurements {
  std::map<RunKey, std::vector<PyramidRun>> runs;       // every repetition of every benchmark
  std::map<int, std::vector<ThreadPair>> thread_pairs;  // the two-thread runs, by pyramid base
  std::vector<WarmStartRun> warm_starts;                // the warm-start measurements
  std::map<std::string, std::vector<TraceRun>> traces;  // every traced run, by method
  std::string load_before;                              // /proc/loadavg when the runs started
  std::string load_after;                               // and when they ended
};

// Named tables: "machine", "pyramids", "peers", "threads", "profile", "scaling", "warm_start",
// "hexagons", "traces" (Markdown), and the CSV files "pyramids.csv", "scaling.csv", "warm_start.csv",
// "hexagons.csv".
using Tables = std::map<std::string, std::string>;
Tables make_tables(const Measurements& measurements);

// Writes every table to `folder` (created if missing), Markdown as <name>.md.
// Throws std::runtime_error naming the file that could not be written.
void write_tables(const Tables& tables, const std::string& folder);

// Replaces, in the Markdown file `doc`, the text between "<!-- begin generated: NAME -->" and
// "<!-- end generated: NAME -->" by table NAME, for every table the file has markers for.
// Throws std::runtime_error for an unreadable file or unmatched markers.
void update_doc(const Tables& tables, const std::string& doc);

}  // namespace lamina
