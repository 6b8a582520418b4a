#include "contact/step_times.h"

namespace lamina {

const char* phase_name(StepPhase phase) {
  switch (phase) {
    case StepPhase::forces: return "1. forces";
    case StepPhase::collision: return "2. collision";
    case StepPhase::cache: return "3. cache";
    case StepPhase::rows: return "4. rows";
    case StepPhase::solve: return "5–6. solve, F_c = Jᵀλ";
    case StepPhase::integrate: return "7. integrate";
    case StepPhase::checks: return "non-finite check";
  }
  return "?";
}

double StepTimes::total() const {
  double sum = 0.0;
  for (const double s : seconds) sum += s;
  return sum;
}

StepTimes StepTimes::since(const StepTimes& earlier) const {
  StepTimes later = *this;
  for (std::size_t p = 0; p < seconds.size(); ++p) later.seconds[p] -= earlier.seconds[p];
  later.steps -= earlier.steps;
  return later;
}

PhaseClock::PhaseClock(StepTimes& times)
    : times_(times), last_(std::chrono::steady_clock::now()) {}

void PhaseClock::lap(StepPhase phase) {
  const auto now = std::chrono::steady_clock::now();
  times_.seconds[static_cast<std::size_t>(phase)] +=
      std::chrono::duration<double>(now - last_).count();
  last_ = now;
}

}  // namespace lamina
