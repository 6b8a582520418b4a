#include "benchmarks/report_profile.h"

#include <sstream>
#include <utility>
#include <vector>

#include "benchmarks/report_summary.h"

namespace lamina::report {
namespace {

// A phase's wall-clock µs per step in a run (its StepTimes over the timed steps).
double phase_us(const PyramidRun& run, StepPhase phase) {
  return run.phases.steps > 0 ? 1e6 * run.phases.of(phase) / static_cast<double>(run.phases.steps)
                              : 0.0;
}

}  // namespace

std::string profile_table(const Measurements& m) {
  std::vector<std::pair<int, const std::vector<PyramidRun>*>> columns;
  for (const int base : bases(m, PyramidShape::boxes)) {
    const auto runs = m.runs.find({"Lamina", base, box2d_iterations});
    if (runs != m.runs.end() && !runs->second.empty()) columns.emplace_back(base, &runs->second);
  }
  const std::vector<ThreadPair>* pairs = nullptr;
  int pairs_base = 0;
  for (const auto& [base, of_base] : m.thread_pairs) {  // by base: the last is the largest
    if (of_base.empty()) continue;
    pairs_base = base;
    pairs = &of_base;
  }
  std::ostringstream out;
  out << "| phase of the step |";
  for (const auto& [base, runs] : columns) out << " base " << base << ": µs per step (share) |";
  if (pairs != nullptr) {
    out << " base " << pairs_base << ", two threads: µs per step | speed-up, median (range) |";
  }
  out << "\n|---|";
  for (std::size_t c = 0; c < columns.size() + (pairs != nullptr ? 2 : 0); ++c) out << "---|";
  out << "\n";
  std::vector<double> totals(columns.size(), 0.0);
  std::vector<std::vector<double>> medians(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    for (int p = 0; p < step_phase_count; ++p) {
      std::vector<double> us;
      for (const PyramidRun& run : *columns[c].second) us.push_back(phase_us(run, StepPhase(p)));
      medians[c].push_back(median(us));
      totals[c] += medians[c].back();
    }
  }
  for (int p = 0; p < step_phase_count; ++p) {
    out << "| " << phase_name(StepPhase(p)) << " |";
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double us = medians[c][static_cast<std::size_t>(p)];
      out << " " << fixed(us, 1) << " (" << fixed(100.0 * us / totals[c], 1) << " %) |";
    }
    if (pairs != nullptr) {
      std::vector<double> two;
      std::vector<double> speed_ups;
      for (const ThreadPair& pair : *pairs) {
        two.push_back(phase_us(pair.two, StepPhase(p)));
        if (two.back() > 0.0) speed_ups.push_back(phase_us(pair.one, StepPhase(p)) / two.back());
      }
      out << " " << fixed(median(two), 1) << " | "
          << (speed_ups.empty() ? "–" : median_and_range(speed_ups, 2, "×")) << " |";
    }
    out << "\n";
  }
  out << "| whole step, the phases' medians summed |";
  for (const double total : totals) out << " " << fixed(total, 1) << " (100 %) |";
  if (pairs != nullptr) out << " | |";
  out << "\n\nWall-clock µs per step over the timed steps of the pyramids table's `pgs` runs "
         "at 8 / 3 sweeps, each phase timed by the World itself (`World::step_times`, "
         "engine/contact/step_times.h: the steady clock read between the phases); medians of the "
         "repetitions, the shares of their sum. Step 5–6 solves the velocity MLCP by PGS with "
         "split impulse's position MLCP beside it and adds F_c = Jᵀλ in the last sweep. The "
         "two-thread column is from the two-thread table's pairs: each phase's time on two "
         "threads, and its one-thread time ÷ its two-thread time in the same pair.\n";
  return out.str();
}

}  // namespace lamina::report
