// What the benchmarks' tables read from the runs (report.cpp: Markdown, report_csv.cpp: CSV):
// the keys of the runs each table compares, a benchmark's repetitions summarised, the bases
// measured, and numbers as fixed-point text.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "benchmarks/report.h"

namespace lamina::report {

// The sweeps Lamina's docs give a standing pyramid: WorldSettings' default
// (docs/ch5-walkthrough.md).
constexpr int recommended_iterations = 10;
constexpr int box2d_iterations = 8;  // Box2D's velocity iterations (Box2dSettings)
constexpr int v3_substeps = 4;       // Box2D v3's substeps

RunKey box2d_key(int base);    // Box2D 2.4.1 at 8 / 3
RunKey islands_key(int base);  // Lamina's default method at its default sweeps
RunKey v3_key(int base);       // Box2D v3 at its substeps
// An engine on the hexagon pyramid, at Box2D's sweeps (8 / 3) for both.
RunKey hexagon_key(const std::string& engine, int base);

// The repetitions of one benchmark: their median times, and the run whose time is nearest the
// median for everything else (contacts, standing: the same in every repetition).
struct Summary {
  int repetitions = 0;
  double ms = 0.0;       // median CPU ms per step
  double ms_min = 0.0;   // fastest repetition
  double ms_max = 0.0;   // slowest repetition
  double wall_ms = 0.0;  // median wall-clock ms per step
  PyramidRun run;        // the median repetition
};
// The benchmark's summary, or none when it was not run.
std::optional<Summary> summary(const Measurements& m, const RunKey& key);

// The bases measured for pyramids of that shape, in increasing order.
std::vector<int> bases(const Measurements& m, PyramidShape shape);

// The median of the values (the mean of the middle two for an even count).
double median(std::vector<double> values);

// `value` with `digits` decimals: "0.833".
std::string fixed(double value, int digits);
// "0.833 (0.753–0.855)", "1.62× (1.34–1.82)": a middle value with `unit`, and a range, each with
// `digits` decimals.
std::string with_range(double middle, double low, double high, int digits,
                       const std::string& unit = "");
// The median of some values and their range (with_range).
std::string median_and_range(const std::vector<double>& values, int digits,
                             const std::string& unit = "");

}  // namespace lamina::report
