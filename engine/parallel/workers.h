// A fixed team of threads for the parts of a step that split into independent pieces, and the
// progress counter through which a pipeline's threads wait on each other (PGS's sweeps,
// constraints/pgs_solver.h). The work is always split the same way, whatever the threads'
// timing, and every value a piece computes is the one the single thread would compute: more
// threads change how fast a step is taken, never one bit of it.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace lamina {

// The largest team, and so at most 2 × 64 runs of a piece of work (runs_on).
constexpr int max_threads = 64;
constexpr int max_runs = 2 * max_threads;

class Workers {
 public:
  // A team of `threads` threads in all: the calling thread and threads − 1 started here, which
  // wait until run() gives them work. Throws std::invalid_argument unless
  // 1 ≤ threads ≤ max_threads.
  explicit Workers(int threads);
  ~Workers();
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;

  int count() const { return static_cast<int>(threads_.size()) + 1; }
  // Whether the threads wait for each other spinning (a team no larger than the machine's
  // cores), or else sleeping: a spinning thread without a core of its own keeps the core from
  // the thread it waits for, and a step took a hundred times as long (docs/performance.md, "Two
  // threads").
  bool spins() const { return spins_; }

  // One turn of a wait that looks again after each (a Progress's value, or several): a pause of
  // the core for the first few thousand turns, then the core yielded to other threads (the
  // thread waited on may have lost its core on a busy machine); yielded at once when the team
  // does not spin. `turns` counts the turns, from 0, and stops counting once they yield.
  void wait_a_turn(int& turns) const;

  // While one is alive, the threads of a team that spins wait for their next piece of work
  // spinning instead of sleeping: a step hands them several pieces with a little serial work
  // between, and waking a sleeping thread costs tens of microseconds (more when its virtual CPU
  // has gone idle). A World keeps one for each step. Nullptr, or a team that sleeps: nothing.
  class Awake {
   public:
    explicit Awake(Workers* workers);
    ~Awake();
    Awake(const Awake&) = delete;
    Awake& operator=(const Awake&) = delete;

   private:
    Workers* workers_;
  };

  // Calls task(t) once for each t in [0, count()): t = 0 on the calling thread, every other t on
  // its own thread, all at once. Returns when every call has returned, and then rethrows the
  // first exception one of them threw (by thread number), if any.
  template <class Task>
  void run(Task&& task) {
    using Plain = std::remove_reference_t<Task>;
    run_erased(const_cast<void*>(static_cast<const void*>(&task)),
               [](void* f, int t) { (*static_cast<Plain*>(f))(t); });
  }

 private:
  void run_erased(void* task, void (*call)(void*, int));
  void serve(int t);  // a worker's loop: wait for a task, run its share, report done

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_;          // a new task, or the end
  std::condition_variable done_;          // the last worker finished its share
  std::atomic<long> generation_{0};       // counts run() calls; a worker runs each once
  std::atomic<int> pending_{0};           // workers still running the current task
  std::atomic<bool> stopping_{false};     // the destructor asks the workers to leave
  std::atomic<int> awake_{0};             // Awake objects alive: spin, do not sleep
  bool spins_ = true;                     // no more threads than cores (machine_cores())
  void* task_ = nullptr;                  // the current task and how to call it
  void (*call_)(void*, int) = nullptr;
  std::vector<std::exception_ptr> failures_;  // per thread, what its share threw
};

// How many runs a piece of work is cut into on `workers`: two per thread, or one (nullptr).
// Thread t of T takes runs t and 2T − 1 − t (runs_of_thread), one from each end of the items'
// order, as PGS takes its parts of the rows (constraints/pgs_solver.h: from both ends of its
// wavefront). A step's bodies, pairs and rows follow one order (a pile's from the ground up), so
// cut the same way in every piece, each thread reads mostly what it wrote itself in the pieces
// before, from its own core's cache; with one run a thread, PGS's first thread swept rows that
// the second had packed (docs/performance.md, "Two threads").
inline int runs_on(const Workers* workers) { return workers != nullptr ? 2 * workers->count() : 1; }

// The two runs (or parts) that thread t takes of `runs`, two per thread: t and runs − 1 − t.
inline std::array<int, 2> runs_of_thread(int t, int runs) { return {t, runs - 1 - t}; }

// Calls task(r) for each run r of runs_on(workers): on the workers' threads (Workers::run), each
// thread its two runs (runs_of_thread) one after the other, or task(0) on the calling thread when
// there are none.
template <class Task>
void run_on(Workers* workers, Task&& task) {
  if (workers != nullptr) {
    const int runs = runs_on(workers);
    workers->run([&](int t) {
      for (const int run : runs_of_thread(t, runs)) task(run);
    });
  } else {
    task(0);
  }
}

// Calls first() and second(), two pieces of work independent of each other: side by side on
// the first two threads of `workers` (the others idle), or one after the other on the calling
// thread when there are not two. For serial work between a step's pieces that splits no
// further, so that the team's second thread is not left waiting through all of it.
template <class First, class Second>
void run_side_by_side(Workers* workers, First&& first, Second&& second) {
  if (workers != nullptr && workers->count() >= 2) {
    workers->run([&](int t) {
      if (t == 0) first();
      if (t == 1) second();
    });
  } else {
    first();
    second();
  }
}

// One T for each run of a team, each on cache lines of its own: runs that keep writing to their
// own T (a vector's end, as they append to it) then never take a line from each other. (Side by
// side in a std::vector, two runs' vectors share a line, and each append of one waits for the
// line to come back from the other core.)
template <class T>
class PerRun {
 public:
  void resize(int runs) { slots_.resize(static_cast<std::size_t>(runs)); }
  int size() const { return static_cast<int>(slots_.size()); }
  T& operator[](int t) { return slots_[static_cast<std::size_t>(t)].value; }
  const T& operator[](int t) const { return slots_[static_cast<std::size_t>(t)].value; }

 private:
  struct alignas(64) Slot {
    T value;
  };
  std::vector<Slot> slots_;
};

// Joins the vectors that the runs of `workers` made, in order, into `out` (its memory reused):
// each run's thread copies its own items into place, so that they stay in the cache of the core
// that made them and will read them next. `of_run` has runs_on(workers) vectors.
template <class T>
void join_runs(const PerRun<std::vector<T>>& of_run, std::vector<T>& out, Workers* workers) {
  std::size_t total = 0;
  for (int t = 0; t < of_run.size(); ++t) total += of_run[t].size();
  out.resize(total);
  run_on(workers, [&](int t) {
    std::size_t at = 0;
    for (int k = 0; k < t; ++k) at += of_run[k].size();
    std::copy(of_run[t].begin(), of_run[t].end(), out.begin() + static_cast<std::ptrdiff_t>(at));
  });
}

// The contiguous share [first, last) of `count` items that part `part` of `parts` takes: equal
// shares in order, the first count % parts of them one item longer. Depends on nothing else.
std::pair<std::size_t, std::size_t> share_of(std::size_t count, int part, int parts);

// Where each run's items go when the runs of `workers` write them side by side, in run order:
// starts[t] is run t's first place, starts[runs] the total. Each run counts its own items
// (count(t) on its own thread), so that what it reads to count them stays in the cache of the
// core that will write them next, not in the first thread's.
using RunStarts = std::array<std::size_t, max_runs + 1>;  // per run, and the end
template <class Count>
RunStarts run_starts(Workers* workers, Count&& count) {
  RunStarts starts{};
  run_on(workers, [&](int t) { starts[static_cast<std::size_t>(t) + 1] = count(t); });
  const std::size_t runs = static_cast<std::size_t>(runs_on(workers));
  for (std::size_t t = 0; t < runs; ++t) starts[t + 1] += starts[t];
  return starts;
}

// How far one thread of a pipeline has got: a count that only grows, published by its thread
// after the work it counts (release) and read by the threads waiting on it (acquire), on a cache
// line of its own.
class alignas(64) Progress {
 public:
  // Starts the count again at `value` (work taken as done before the pipeline starts), before
  // the threads that publish and read it are started.
  void reset(long value = 0) { value_.store(value, std::memory_order_relaxed); }
  void publish(long value) { value_.store(value, std::memory_order_release); }
  // The count now (acquire: what was written before it was published is seen).
  long value() const { return value_.load(std::memory_order_acquire); }

 private:
  std::atomic<long> value_{0};
};

// The cores this process may run on (its CPU affinity), 0 when not known.
int machine_cores();
// Whether a team of `threads` has a core for each thread (true when the cores are not known):
// a Workers of that many spins while it waits.
bool fits_cores(int threads);

}  // namespace lamina
