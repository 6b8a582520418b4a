// The benchmarks' profile of the step (docs/performance.md, *What the time goes to*): where
// `pgs`'s step spends its time, phase by phase of the chapter-5 walk-through, from the World's
// own clock (World::step_times); report.cpp names it in make_tables.
#pragma once

#include <string>

#include "benchmarks/report.h"

namespace lamina::report {

// Each phase's µs a step and share at every base of the one-thread runs at 8 / 3 sweeps, and at
// the largest base of the two-thread runs each phase's time and speed-up from the same pairs.
std::string profile_table(const Measurements& m);

}  // namespace lamina::report
