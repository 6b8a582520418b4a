// Issue 19's trace bar: what writing a JSON trace costs beside the physics it records.
//
//   scene    pyramid_scene(base) (pyramid_runs.h), by the method `solver`
//   run      `steps` steps as `lamina run pyramid:N --trace FILE.jsonl` makes them: each step is
//            World::step, then its record (trace_step) and its line written by TraceWriter into
//            a file in the system's temporary folder (removed afterwards)
//   time     the two timed apart in the same run by the thread's CPU clock, which counts the
//            kernel's time in the thread's system calls too (copying the text into the page
//            cache is part of writing a trace); so the machine's moods touch both alike
#pragma once

#include <string>

namespace lamina {

struct TraceRun {
  double physics_ms = 0.0;  // CPU ms per step in World::step
  double trace_ms = 0.0;    // CPU ms per step recording it and writing its line
  double megabytes = 0.0;   // the trace file's size, in MB (10⁶ bytes)
};

TraceRun run_traced_pyramid(int base, const std::string& solver, int steps);

}  // namespace lamina
