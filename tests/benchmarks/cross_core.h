// The machine's first two CPUs, as the two-thread table (docs/performance.md) has to be read
// beside them: how long a cache line takes to go from one to the other and back, and how fast
// each runs the same one-thread work. A two-thread step hands data between its threads wherever
// its pieces meet, and each of its pieces is cut into equal halves, so it goes at the pace of the
// slower CPU: on a virtual machine both change with where the host puts the two virtual CPUs
// and what else runs beside them, and the speed-up with them.
#pragma once

#include <functional>
#include <optional>

namespace lamina {

// The mean round trip in ns over `round_trips` hand-overs, or none when the machine has fewer
// than two CPUs this process may run on.
std::optional<double> cross_core_round_trip_ns(long round_trips = 200000);

// The time of `work` on the first CPU ÷ its time on the second: the calling thread runs it
// pinned to each, in the order first, second, second, first (so that what one run leaves
// warm for the next favours neither), and `work` returns the time it measured; the means of
// each CPU's two are divided. None when the process may run on fewer than two CPUs.
std::optional<double> first_cpu_time_ratio(const std::function<double()>& work);

}  // namespace lamina
