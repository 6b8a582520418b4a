// Where a World's steps spend their time, phase by phase of the chapter-5 walk-through
// (world.h): the wall-clock time of each phase, summed over the steps taken. A PhaseClock reads
// the steady clock once between two phases (some 20 ns a reading, against a step of hundreds of
// µs) and changes nothing that the step computes. docs/performance.md's profile of the step
// (*What the time goes to*) is made from these sums.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>

namespace lamina {

// The phases as World::step takes them, in order. `solve` is steps 5 and 6 (PGS, with split
// impulse's position solve beside it, and F_c = Jᵀ λ), `integrate` step 7; a chapter-6 method
// (step_method.h) takes 5 to 7 in one piece, all of it counted as `solve`. `checks` is the look
// for a body left non-finite.
enum class StepPhase { forces, collision, cache, rows, solve, integrate, checks };
inline constexpr int step_phase_count = 7;

// The phase's name with the numbers of the walk-through, e.g. "2. collision".
const char* phase_name(StepPhase phase);

struct StepTimes {
  std::array<double, step_phase_count> seconds{};  // per phase, summed over the steps
  long steps = 0;                                  // the steps summed

  double of(StepPhase phase) const { return seconds[static_cast<std::size_t>(phase)]; }
  double total() const;  // of every phase, in s
  // The sums of the steps taken after `earlier` (a copy of these sums taken then).
  StepTimes since(const StepTimes& earlier) const;
};

// Times one step's phases in turn: lap(p) adds the time since the clock was made, or since the
// last lap, to phase p.
class PhaseClock {
 public:
  explicit PhaseClock(StepTimes& times);
  void lap(StepPhase phase);

 private:
  StepTimes& times_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace lamina
