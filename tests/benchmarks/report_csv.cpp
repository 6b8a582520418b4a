#include "benchmarks/report_csv.h"

#include <sstream>

#include "benchmarks/report_summary.h"

namespace lamina::report {

// Every benchmark on pyramids of that shape, a line each; the third column counts the bodies
// under the shape's name ("boxes", "hexagons").
std::string runs_csv(const Measurements& m, PyramidShape shape) {
  std::ostringstream out;
  out << "engine,base," << shape_name(shape)
      << ",velocity_iterations,position_iterations,repetitions,ms_per_step,"
         "ms_per_step_min,ms_per_step_max,wall_ms_per_step,contact_points,apex_shift_m,"
         "largest_sideways_m,standing\n";
  for (const auto& [key, runs] : m.runs) {
    if (key.shape != shape) continue;
    const Summary s = *summary(m, key);
    out << key.engine << ',' << key.base << ',' << s.run.bodies << ',' << key.iterations << ','
        << s.run.position_iterations << ',' << s.repetitions << ',' << fixed(s.ms, 4) << ','
        << fixed(s.ms_min, 4) << ',' << fixed(s.ms_max, 4) << ',' << fixed(s.wall_ms, 4) << ','
        << s.run.contact_points << ',' << fixed(s.run.apex_shift, 4) << ','
        << fixed(s.run.largest_sideways, 4) << ',' << (s.run.standing() ? 1 : 0) << '\n';
  }
  return out.str();
}

std::string scaling_csv(const Measurements& m) {
  std::ostringstream out;
  out << "base,boxes,lamina_ms_per_step,box2d_ms_per_step,lamina_velocity_rows,"
         "box2d_velocity_rows,lamina_us_per_row_sweep,box2d_us_per_row_sweep,"
         "islands_ms_per_step,box2d_v3_ms_per_step\n";
  // a base an engine was not run at (or Box2D v3 not built): NaN, which the plot skips
  const auto ms_or_nan = [](const std::optional<Summary>& s) {
    return s ? fixed(s->ms, 4) : std::string("NaN");
  };
  for (const int base : bases(m, PyramidShape::boxes)) {
    const std::optional<Summary> l = summary(m, {"Lamina", base, box2d_iterations});
    const std::optional<Summary> b = summary(m, box2d_key(base));
    if (!l || !b) continue;
    out << base << ',' << l->run.bodies << ',' << fixed(l->ms, 4) << ',' << fixed(b->ms, 4) << ','
        << l->run.velocity_rows << ',' << b->run.velocity_rows << ','
        << fixed(l->run.us_per_row_sweep(), 5) << ',' << fixed(b->run.us_per_row_sweep(), 5)
        << ',' << ms_or_nan(summary(m, islands_key(base))) << ','
        << ms_or_nan(summary(m, v3_key(base))) << '\n';
  }
  return out.str();
}

std::string warm_start_csv(const Measurements& m) {
  std::ostringstream out;
  out << "base,first_step,steps,reduction,warm_sweeps,cold_sweeps\n";
  for (const WarmStartRun& w : m.warm_starts) {
    for (size_t r = 0; r < w.reductions.size(); ++r) {
      out << w.base << ',' << w.first_step << ',' << w.steps << ',' << w.reductions[r] << ','
          << fixed(w.warm_sweeps[r], 2) << ',' << fixed(w.cold_sweeps[r], 2) << '\n';
    }
  }
  return out.str();
}

}  // namespace lamina::report
