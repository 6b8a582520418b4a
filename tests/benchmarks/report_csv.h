// The benchmarks' CSV tables, for the plot (time_per_step.gp) and for reading back; report.cpp
// names them in make_tables.
#pragma once

#include <string>

#include "benchmarks/report.h"

namespace lamina::report {

// Every benchmark on pyramids of that shape, a line each.
std::string runs_csv(const Measurements& m, PyramidShape shape);
// Per base: both engines' time per step, rows and time per row-sweep; islands and Box2D v3.
std::string scaling_csv(const Measurements& m);
// The warm-start measurements, a line per asked reduction.
std::string warm_start_csv(const Measurements& m);

}  // namespace lamina::report
