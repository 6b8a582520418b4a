#include "benchmarks/report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>
#include <tuple>

#include "benchmarks/report_csv.h"
#include "benchmarks/report_profile.h"
#include "benchmarks/report_summary.h"

#ifdef LAMINA_HAVE_BOX2D_V3
#include "benchmarks/box2d_v3_runs.h"
#endif

namespace lamina {
namespace {

using namespace report;

std::string read_first_line(const std::string& path, const std::string& prefix) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(prefix, 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown";
}

std::string machine_table(const Measurements& m) {
  std::ostringstream out;
  out << "| | |\n|---|---|\n"
      << "| CPU | " << read_first_line("/proc/cpuinfo", "model name") << " |\n"
      << "| cores | " << std::thread::hardware_concurrency() << " (the benchmarks use one) |\n"
      << "| compiler | GCC " << __VERSION__ << ", -O2 -ffp-contract=off (Release) |\n"
      << "| Box2D | " << LAMINA_BOX2D_VERSION << " (Debian's libbox2d) |\n"
#ifdef LAMINA_HAVE_BOX2D_V3
      << "| Box2D v3 | " << box2d_v3_version() << " (built from its source by "
         "-DLAMINA_BOX2D_V3_DIR: -O3, AVX2, one thread, " << box2d_v3_substeps << " substeps) |\n"
#else
      << "| Box2D v3 | not built (configure with -DLAMINA_BOX2D_V3_DIR=<its source>) |\n"
#endif
      << "| load average (1, 5, 15 min; running, total tasks) | before: " << m.load_before
      << "; after: " << m.load_after << " |\n";
  return out.str();
}

std::string standing_cells(const PyramidRun& run) {
  return fixed(run.apex_shift, 3) + " | " + fixed(run.largest_sideways, 3) + " | " +
         (run.standing() ? "yes" : "no");
}

// The median CPU ms per step and the fastest and slowest repetitions.
std::string ms_cells(const Summary& s) { return with_range(s.ms, s.ms_min, s.ms_max, 3); }

// "0.83× — met" or "1.12× — missed by 0.12 (12 %)" against a bar.
std::string against(double ratio, double bar) {
  if (ratio <= bar) return fixed(ratio, 2) + "× ≤ " + fixed(bar, 1) + ": met";
  return fixed(ratio, 2) + "× > " + fixed(bar, 1) + ": missed by " + fixed(ratio - bar, 2) + " (" +
         fixed(100.0 * (ratio - bar) / bar, 0) + " %)";
}

void pyramid_rows(const Measurements& m, int base, std::ostringstream& out,
                  std::ostringstream& verdicts) {
  const std::optional<Summary> box2d = summary(m, box2d_key(base));
  const RunKey keys[] = {box2d_key(base), {"Lamina", base, recommended_iterations},
                         {"Lamina", base, box2d_iterations}};
  for (const RunKey& key : keys) {
    const std::optional<Summary> s = summary(m, key);
    if (!s) continue;
    const bool lamina = key.engine == "Lamina";
    const std::string ratio = lamina && box2d ? fixed(s->ms / box2d->ms, 2) + "× (" +
                                                    fixed(s->ms_min / box2d->ms_min, 2) + "×)"
                                              : "–";
    out << "| " << base << " (" << s->run.bodies << " boxes) | " << key.engine
        << (lamina && key.iterations == recommended_iterations ? " (recommended)" : "") << " | "
        << key.iterations << " / " << s->run.position_iterations << " | " << ms_cells(*s) << " | "
        << fixed(s->wall_ms, 3) << " | " << ratio << " | " << standing_cells(s->run) << " |\n";
    if (lamina && box2d && key.iterations == box2d_iterations) {
      verdicts << "- base " << base << ", equal sweeps (8 / 3), medians: Lamina ÷ Box2D = "
               << against(s->ms / box2d->ms, 1.0) << " (target); "
               << against(s->ms / box2d->ms, 0.5) << " (goal). Fastest runs: " << fixed(s->ms_min / box2d->ms_min, 2) << "×.\n";
    }
  }
}

std::string pyramids_table(const Measurements& m) {
  std::ostringstream out;
  std::ostringstream verdicts;
  out << "| pyramid | engine | sweeps (velocity / position) | CPU ms per step, median (range) | "
         "wall ms per step | Lamina ÷ Box2D, medians (fastest runs) | 10 s: apex moved (m) | "
         "10 s: largest sideways move (m) | standing |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const int base : {20, 40}) pyramid_rows(m, base, out, verdicts);
  return out.str() + "\n" + verdicts.str();
}

// Issue 19's bars, a line per base: Lamina's `pgs` at Box2D's 8 sweeps against Box2D 2.4.1,
// and Lamina's default method `islands` at its default sweeps against Box2D v3 (when built).
std::string peers_table(const Measurements& m) {
  std::ostringstream out;
  out << "| pyramid | Box2D 2.4.1, 8 / 3 | Lamina `pgs`, 8 / 3 | `pgs` ÷ Box2D 2.4.1 | Lamina "
         "`islands`, " << recommended_iterations << " / 3 | Box2D v3, " << v3_substeps
      << " substeps | `islands` ÷ Box2D v3 | `pgs` ÷ Box2D v3 |\n|---|---|---|---|---|---|---|---|\n";
  const auto ratio = [](const std::optional<Summary>& a, const std::optional<Summary>& b) {
    return a && b ? fixed(a->ms / b->ms, 2) + "×" : std::string("–");
  };
  const auto ms = [](const std::optional<Summary>& s) { return s ? fixed(s->ms, 3) : std::string("–"); };
  std::ostringstream verdicts;
  for (const int base : bases(m, PyramidShape::boxes)) {
    const std::optional<Summary> box2d = summary(m, box2d_key(base));
    const std::optional<Summary> pgs = summary(m, {"Lamina", base, box2d_iterations});
    const std::optional<Summary> islands = summary(m, islands_key(base));
    const std::optional<Summary> v3 = summary(m, v3_key(base));
    if (!islands && !v3) continue;
    out << "| " << base << " | " << ms(box2d) << " | " << ms(pgs) << " | " << ratio(pgs, box2d)
        << " | " << ms(islands) << " | " << ms(v3) << " | " << ratio(islands, v3) << " | "
        << ratio(pgs, v3) << " |\n";
    if (pgs && box2d) {
      verdicts << "- base " << base << ": `pgs` ÷ Box2D 2.4.1 = " << against(pgs->ms / box2d->ms, 0.5);
      if (islands && v3) verdicts << "; `islands` ÷ Box2D v3 = " << against(islands->ms / v3->ms, 1.5);
      verdicts << ".\n";
    }
  }
  out << "\nCPU ms per step, medians of the repetitions, one thread each.\n" << verdicts.str();
  return out.str();
}

// A virtual machine's two CPUs may be near each other (sharing a cache: a round trip of about
// 140 ns measured) or far apart (about 580 ns), as the host places them, and the host moves them
// while the benchmarks run; the pairs are told apart at this round trip, between the two.
constexpr double near_cores_ns = 300.0;

// Issue 19's two threads: wall-clock time per step of `pgs` at 8 / 3 on one thread and on two
// (the CPU time of the stepping thread leaves out the other's work), run in pairs; the speed-up
// is the median of the pairs' own, beside the cores' round trip and their one-thread speeds
// measured before each pair.
std::string threads_table(const Measurements& m) {
  std::ostringstream out;
  out << "| pyramid | one thread, wall ms per step | two threads, wall ms per step | speed-up, "
         "median (range) of the pairs | a cache line between the cores and back, ns, median "
         "(range) | speed-up with the cores near (round trip < "
      << near_cores_ns << " ns): pairs, median | with the cores far: pairs, median "
         "| one thread's time on the first CPU ÷ on the second, median (range) "
         "|\n|---|---|---|---|---|---|---|---|\n";
  std::ostringstream verdicts;
  for (const auto& [base, pairs] : m.thread_pairs) {
    if (pairs.empty()) continue;
    std::vector<double> one;
    std::vector<double> two;
    std::vector<double> speed_ups;
    std::vector<double> round_trips;
    std::vector<double> cpu_ratios;
    std::array<std::vector<double>, 2> by_distance;  // the speed-ups with the cores near, far
    for (const ThreadPair& pair : pairs) {
      one.push_back(pair.one.wall_ms_per_step);
      two.push_back(pair.two.wall_ms_per_step);
      speed_ups.push_back(pair.one.wall_ms_per_step / pair.two.wall_ms_per_step);
      if (pair.first_cpu_ratio) cpu_ratios.push_back(*pair.first_cpu_ratio);
      if (!pair.round_trip_ns) continue;
      round_trips.push_back(*pair.round_trip_ns);
      by_distance[*pair.round_trip_ns < near_cores_ns ? 0 : 1].push_back(speed_ups.back());
    }
    const double speed_up = median(speed_ups);
    out << "| " << base << " | " << fixed(median(one), 3) << " | " << fixed(median(two), 3) << " | "
        << median_and_range(speed_ups, 2, "×") << " | ";
    if (round_trips.empty()) {
      out << "– (one CPU) | – | – |";
    } else {
      out << median_and_range(round_trips, 0) << " |";
      for (const std::vector<double>& group : by_distance) {
        out << " " << group.size();
        if (!group.empty()) out << ", " << fixed(median(group), 2) << "×";
        out << " |";
      }
    }
    out << " " << (cpu_ratios.empty() ? "–" : median_and_range(cpu_ratios, 2)) << " |\n";
    verdicts << "- base " << base << ": speed-up " << fixed(speed_up, 2) << "× "
             << (speed_up >= 1.7 ? "≥ 1.7: met" : "< 1.7: missed") << ".\n";
  }
  out << "\nEach repetition runs the pyramid on one thread, then on two, right after timing a cache "
         "line's round trip between the two cores and one thread of pyramid:20 (`pgs`, 8 / 3) "
         "pinned to each core; medians of the repetitions. Every piece of the two-thread step is "
         "cut into equal halves, so it goes at the pace of the slower core: with one core r "
         "times slower than the other, against one thread on the faster core the speed-up is at "
         "most about 2 ÷ r. The same state bit for bit on both (tests/test_threads.cpp). The "
         "verdicts take every pair.\n"
      << verdicts.str();
  return out.str();
}

// Least-squares slope of ln(ms) against ln(velocity rows): 1 is linear growth.
std::optional<double> growth_exponent(const Measurements& m, const std::string& engine) {
  std::vector<std::pair<double, double>> points;
  for (const int base : bases(m, PyramidShape::boxes)) {
    const std::optional<Summary> s = summary(m, {engine, base, box2d_iterations});
    if (s) points.emplace_back(std::log(s->run.velocity_rows), std::log(s->ms));
  }
  if (points.size() < 2) return std::nullopt;
  double mx = 0.0, my = 0.0;
  for (const auto& [x, y] : points) mx += x / points.size(), my += y / points.size();
  double sxy = 0.0, sxx = 0.0;
  for (const auto& [x, y] : points) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
  return sxy / sxx;
}

std::string scaling_table(const Measurements& m) {
  std::ostringstream out;
  out << "| base | boxes | contact points, Lamina / Box2D | velocity rows, Lamina / Box2D | "
         "Lamina ms per step | Box2D ms per step | Lamina ÷ Box2D | Lamina µs per row-sweep | "
         "Box2D µs per row-sweep |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const int base : bases(m, PyramidShape::boxes)) {
    const std::optional<Summary> l = summary(m, {"Lamina", base, box2d_iterations});
    const std::optional<Summary> b = summary(m, box2d_key(base));
    if (!l || !b) continue;
    out << "| " << base << " | " << l->run.bodies << " | " << l->run.contact_points << " / "
        << b->run.contact_points << " | " << l->run.velocity_rows << " / " << b->run.velocity_rows
        << " | " << fixed(l->ms, 3) << " | " << fixed(b->ms, 3) << " | " << fixed(l->ms / b->ms, 2)
        << "× | " << fixed(l->run.us_per_row_sweep(), 4) << " | "
        << fixed(b->run.us_per_row_sweep(), 4) << " |\n";
  }
  const std::optional<double> lamina = growth_exponent(m, "Lamina");
  const std::optional<double> box2d = growth_exponent(m, "Box2D");
  if (lamina && box2d) {
    out << "\nGrowth of the time per step with the velocity rows, as the exponent k of "
           "time ∝ rowsᵏ fitted over these bases (1 is linear): Lamina "
        << fixed(*lamina, 2) << ", Box2D " << fixed(*box2d, 2) << ".\n";
  }
  return out.str();
}

std::string warm_start_table(const Measurements& m) {
  std::ostringstream out;
  out << "| pyramid | steps measured | ‖W‖ asked, ÷ ‖W(λ = 0)‖ | sweeps from the cached λ | "
         "sweeps from λ = 0 |\n|---|---|---|---|---|\n";
  for (const WarmStartRun& w : m.warm_starts) {
    for (size_t r = 0; r < w.reductions.size(); ++r) {
      out << "| base " << w.base << " | " << w.first_step << "–" << w.first_step + w.steps - 1
          << " | " << w.reductions[r] << " | " << fixed(w.warm_sweeps[r], 1) << " | "
          << fixed(w.cold_sweeps[r], 1) << " |\n";
    }
  }
  out << "\nAfter 10 sweeps (the recommended count), ‖W‖ ÷ ‖W(λ = 0)‖:";
  for (const WarmStartRun& w : m.warm_starts) {
    out << " base " << w.base << ", " << fixed(w.warm_residual_10, 4) << " from the cached λ and "
        << fixed(w.cold_residual_10, 4) << " from λ = 0;";
  }
  out << " at most " << (m.warm_starts.empty() ? 0 : m.warm_starts.front().max_sweeps)
      << " sweeps were tried.\n";
  return out.str();
}

// "0.257 / 0.133": one number of each engine's pyramid, Lamina's first.
std::string pair_cell(double lamina, double box2d) {
  return fixed(lamina, 3) + " / " + fixed(box2d, 3);
}

// Hexagons ÷ boxes of the same count (the box pyramid of the same base, 8 / 3 sweeps) for one
// engine, medians: "1.93×", or "–" without the box run.
std::string against_boxes(const Measurements& m, const std::string& engine, int base,
                          const Summary& hexagons) {
  const std::optional<Summary> boxes = summary(m, {engine, base, box2d_iterations});
  return boxes ? fixed(hexagons.ms / boxes->ms, 2) + "×" : "–";
}

// The hexagon pyramids, a line per base: both engines at 8 / 3 sweeps side by side, then each
// engine's time against its box pyramid of the same count.
std::string hexagons_table(const Measurements& m) {
  std::ostringstream out;
  std::string boxes;  // "base 10, Lamina 1.93× and Box2D 1.20×; base 20, …"
  out << "| base | hexagons | contact points, Lamina / Box2D | Lamina CPU ms per step, median "
         "(range) | Box2D CPU ms per step, median (range) | Lamina ÷ Box2D, medians (fastest "
         "runs) | 10 s: apex moved (m), Lamina / Box2D | 10 s: largest sideways move (m), "
         "Lamina / Box2D | standing, Lamina / Box2D |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const int base : bases(m, PyramidShape::hexagons)) {
    const std::optional<Summary> l = summary(m, hexagon_key("Lamina", base));
    const std::optional<Summary> b = summary(m, hexagon_key("Box2D", base));
    if (!l || !b) continue;
    out << "| " << base << " | " << l->run.bodies << " | " << l->run.contact_points << " / "
        << b->run.contact_points << " | " << ms_cells(*l) << " | " << ms_cells(*b) << " | "
        << fixed(l->ms / b->ms, 2) << "× (" << fixed(l->ms_min / b->ms_min, 2) << "×) | "
        << pair_cell(l->run.apex_shift, b->run.apex_shift) << " | "
        << pair_cell(l->run.largest_sideways, b->run.largest_sideways) << " | "
        << (l->run.standing() ? "yes" : "no") << " / " << (b->run.standing() ? "yes" : "no")
        << " |\n";
    boxes += (boxes.empty() ? " base " : "; base ") + std::to_string(base) + ", Lamina " +
             against_boxes(m, "Lamina", base, *l) + " and Box2D " +
             against_boxes(m, "Box2D", base, *b);
  }
  out << "\nStanding: the box pyramid's bar, the apex within " << fixed(apex_bar, 1)
      << " m of its start and no hexagon moved more than " << fixed(sideways_bar, 1)
      << " m sideways. CPU time per step against the box pyramid of the same count (the same "
         "base, 8 / 3 sweeps, this run), medians, hexagons ÷ boxes:"
      << boxes << ".\n";
  return out.str();
}

// Issue 19's trace bar, a line per method: the CPU ms per step of the physics and of writing
// its trace, timed apart in the same runs (trace_runs.h), and the trace ÷ physics of each run.
std::string traces_table(const Measurements& m) {
  std::ostringstream out;
  std::ostringstream verdicts;
  out << "| method | physics (`World::step`), CPU ms per step | trace (record, JSON line, "
         "written), CPU ms per step | trace ÷ physics | trace file |\n|---|---|---|---|---|\n";
  std::size_t repetitions = 0;
  for (const auto& [solver, runs] : m.traces) {
    std::vector<double> physics, trace, ratio;
    for (const TraceRun& run : runs) {
      physics.push_back(run.physics_ms);
      trace.push_back(run.trace_ms);
      ratio.push_back(run.trace_ms / run.physics_ms);
    }
    repetitions = runs.size();
    out << "| `" << solver << "` | " << fixed(median(physics), 3) << " | "
        << fixed(median(trace), 3) << " | " << fixed(median(ratio), 2) << "× | "
        << fixed(runs.front().megabytes, 0) << " MB |\n";
    verdicts << "- `" << solver << "`: trace ÷ physics = " << against(median(ratio), 1.0) << ".\n";
  }
  out << "\npyramid:20, " << standing_steps << " steps a run, medians of " << repetitions
      << " runs. The thread's CPU time, user and system: the kernel's copying of the text into "
         "its page cache is part of writing the trace. The ratio is each run's, so both sides "
         "of it saw the same machine.\n"
      << verdicts.str();
  return out.str();
}

}  // namespace

bool RunKey::operator<(const RunKey& o) const {
  return std::tie(shape, engine, base, iterations) <
         std::tie(o.shape, o.engine, o.base, o.iterations);
}

Tables make_tables(const Measurements& m) {
  return {{"machine", machine_table(m)},
          {"pyramids", pyramids_table(m)},
          {"peers", peers_table(m)},
          {"threads", threads_table(m)},
          {"profile", profile_table(m)},
          {"scaling", scaling_table(m)},
          {"warm_start", warm_start_table(m)},
          {"hexagons", hexagons_table(m)},
          {"traces", traces_table(m)},
          {"pyramids.csv", runs_csv(m, PyramidShape::boxes)},
          {"scaling.csv", scaling_csv(m)},
          {"warm_start.csv", warm_start_csv(m)},
          {"hexagons.csv", runs_csv(m, PyramidShape::hexagons)}};
}

}  // namespace lamina
