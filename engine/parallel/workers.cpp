#include "parallel/workers.h"

#include <sched.h>

#include <chrono>
#include <stdexcept>
#include <string>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace lamina {

Workers::Workers(int threads) {
  if (threads < 1 || threads > max_threads) {
    throw std::invalid_argument("threads must be 1 to " + std::to_string(max_threads) + ", got " +
                                std::to_string(threads));
  }
  spins_ = fits_cores(threads);
  failures_.resize(static_cast<std::size_t>(threads));
  threads_.reserve(static_cast<std::size_t>(threads - 1));
  for (int t = 1; t < threads; ++t) threads_.emplace_back([this, t] { serve(t); });
}

Workers::~Workers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_.store(true);
  }
  wake_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

namespace {

// A step hands its threads one piece of work after another, often within microseconds: a thread
// that has finished spins this long for the next before it sleeps (waking a sleeping thread
// takes some tens of microseconds).
constexpr auto spin_before_sleep = std::chrono::microseconds(100);

void cpu_pause() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();  // let the other hyperthread of a core run while this one spins
#endif
}

// Spins until done(), or for spin_before_sleep once keep_spinning() is false; true if done().
template <class Done, class KeepSpinning>
bool spin_until(Done&& done, KeepSpinning&& keep_spinning) {
  auto until = std::chrono::steady_clock::now() + spin_before_sleep;
  for (int spins = 0; !done(); ++spins) {
    cpu_pause();
    if (spins % 64 != 63) continue;
    const auto now = std::chrono::steady_clock::now();
    if (keep_spinning()) {
      until = now + spin_before_sleep;
    } else if (now > until) {
      return false;
    }
  }
  return true;
}

}  // namespace

Workers::Awake::Awake(Workers* workers)
    : workers_(workers != nullptr && workers->spins() ? workers : nullptr) {
  if (workers_ == nullptr) return;
  workers_->awake_.fetch_add(1);
  {
    std::lock_guard<std::mutex> lock(workers_->mutex_);  // a sleeping thread checks under it
  }
  workers_->wake_.notify_all();  // sleeping threads start spinning
}

Workers::Awake::~Awake() {
  if (workers_ != nullptr) workers_->awake_.fetch_sub(1);
}

void Workers::run_erased(void* task, void (*call)(void*, int)) {
  if (!threads_.empty()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      task_ = task;
      call_ = call;
      pending_.store(static_cast<int>(threads_.size()));
      generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
  }
  try {
    call(task, 0);
  } catch (...) {
    failures_[0] = std::current_exception();
  }
  if (!threads_.empty()) {
    const auto finished = [this] { return pending_.load(std::memory_order_acquire) == 0; };
    if (!spins_ || !spin_until(finished, [] { return true; })) {
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, finished);
    }
  }
  for (std::exception_ptr& failure : failures_) {
    if (failure) {
      std::exception_ptr first = std::move(failure);
      for (std::exception_ptr& other : failures_) other = nullptr;
      std::rethrow_exception(first);
    }
  }
}

void Workers::serve(int t) {
  long seen = 0;
  for (;;) {
    const auto woken = [&] {
      return stopping_.load() || generation_.load(std::memory_order_acquire) != seen;
    };
    const auto kept_awake = [this] { return awake_.load(std::memory_order_relaxed) > 0; };
    while (!spins_ || !spin_until(woken, kept_awake)) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return woken() || kept_awake(); });
      if (woken()) break;
    }
    if (stopping_.load()) return;
    seen = generation_.load(std::memory_order_acquire);
    try {
      call_(task_, t);
    } catch (...) {
      failures_[static_cast<std::size_t>(t)] = std::current_exception();
    }
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      std::lock_guard<std::mutex> lock(mutex_);  // the caller is waiting, or about to check
      done_.notify_one();
    }
  }
}

int machine_cores() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) return CPU_COUNT(&allowed);
  return static_cast<int>(std::thread::hardware_concurrency());  // 0: not known
}

bool fits_cores(int threads) {
  const int cores = machine_cores();
  return cores == 0 || threads <= cores;
}

std::pair<std::size_t, std::size_t> share_of(std::size_t count, int part, int parts) {
  const std::size_t n = static_cast<std::size_t>(parts);
  const std::size_t k = static_cast<std::size_t>(part);
  const std::size_t base = count / n;
  const std::size_t longer = count % n;  // the first `longer` parts take one item more
  const std::size_t first = k * base + (k < longer ? k : longer);
  return {first, first + base + (k < longer ? 1 : 0)};
}

void Workers::wait_a_turn(int& turns) const {
  constexpr int pauses = 4096;
  if (spins_ && turns < pauses) {
    cpu_pause();
    ++turns;
  } else {
    std::this_thread::yield();
  }
}

}  // namespace lamina
