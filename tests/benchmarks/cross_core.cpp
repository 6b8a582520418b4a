#include "benchmarks/cross_core.h"

#include <pthread.h>
#include <sched.h>

#include <array>
#include <atomic>
#include <chrono>
#include <thread>

namespace lamina {

namespace {

// The first `count` CPUs this process may run on, or fewer when it may run on fewer.
int allowed_cpus(int count, int* cpus) {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return 0;
  int found = 0;
  for (int c = 0; c < CPU_SETSIZE && found < count; ++c) {
    if (CPU_ISSET(c, &allowed)) cpus[found++] = c;
  }
  return found;
}

// Keeps the calling thread on `cpu`; returns the set it had, to be given back.
cpu_set_t pin_to(int cpu) {
  cpu_set_t before;
  CPU_ZERO(&before);
  pthread_getaffinity_np(pthread_self(), sizeof before, &before);
  cpu_set_t only;
  CPU_ZERO(&only);
  CPU_SET(cpu, &only);
  pthread_setaffinity_np(pthread_self(), sizeof only, &only);
  return before;
}

}  // namespace

std::optional<double> cross_core_round_trip_ns(long round_trips) {
  int cpus[2];
  if (allowed_cpus(2, cpus) < 2 || round_trips < 1) return std::nullopt;
  // each counter on a cache line of its own: the line of `ping` goes over, that of `pong` back
  alignas(64) std::atomic<long> ping{0};
  alignas(64) std::atomic<long> pong{0};
  std::thread other([&] {
    pin_to(cpus[1]);
    for (long i = 1; i <= round_trips; ++i) {
      while (ping.load(std::memory_order_acquire) != i) {
      }
      pong.store(i, std::memory_order_release);
    }
  });
  const cpu_set_t before = pin_to(cpus[0]);
  const auto start = std::chrono::steady_clock::now();
  for (long i = 1; i <= round_trips; ++i) {
    ping.store(i, std::memory_order_release);
    while (pong.load(std::memory_order_acquire) != i) {
    }
  }
  const std::chrono::duration<double, std::nano> took = std::chrono::steady_clock::now() - start;
  other.join();
  pthread_setaffinity_np(pthread_self(), sizeof before, &before);
  return took.count() / static_cast<double>(round_trips);
}

std::optional<double> first_cpu_time_ratio(const std::function<double()>& work) {
  int cpus[2];
  if (allowed_cpus(2, cpus) < 2) return std::nullopt;
  std::array<double, 2> took{};  // per CPU, the sum of its two runs' times
  const cpu_set_t before = pin_to(cpus[0]);
  for (const int k : {0, 1, 1, 0}) {
    pin_to(cpus[k]);
    took[static_cast<std::size_t>(k)] += work();
  }
  pthread_setaffinity_np(pthread_self(), sizeof before, &before);
  return took[0] / took[1];
}

}  // namespace lamina
