// How long a cache line takes to go from one core to another and back on this machine: two
// threads, one on each of the first two CPUs, hand a counter to each other. A two-thread step
// hands data between its threads wherever its pieces meet, so this round trip is what the
// two-thread table (docs/performance.md) has to be read beside: on a virtual machine it changes
// with where the host puts the two virtual CPUs, and the speed-up with it.
#pragma once

#include <optional>

namespace lamina {

// The mean round trip in ns over `round_trips` hand-overs, or none when the machine has fewer
// than two CPUs this process may run on.
std::optional<double> cross_core_round_trip_ns(long round_trips = 200000);

}  // namespace lamina
