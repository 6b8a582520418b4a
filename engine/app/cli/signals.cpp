#include "app/cli/signals.h"

#include <atomic>
#include <csignal>

#include <signal.h>

#include "output/unfinished_files.h"

namespace lamina::cli {
namespace {

// The signal noted by the handler; lock-free, so safe to set in a handler on any thread.
std::atomic<int> noted_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

// Whether SIGINT (interrupted), SIGTERM (terminated) has arrived once already.
std::atomic<bool> interrupted{false}, terminated{false};
static_assert(std::atomic<bool>::is_always_lock_free);

// Dies by `signal`: its default action, raised again. The signal is blocked while its handler
// runs, so it is delivered, and kills, when the handler returns.
void die_by(int signal) {
  struct sigaction fatal {};
  fatal.sa_handler = SIG_DFL;
  sigemptyset(&fatal.sa_mask);
  sigaction(signal, &fatal, nullptr);
  raise(signal);
}

// Only async-signal-safe calls: atomics, unlink() (in remove_unfinished_files), sigaction, raise.
void on_stop_signal(int signal) {
  std::atomic<bool>& arrived = signal == SIGINT ? interrupted : terminated;
  if (!arrived.exchange(true)) {
    noted_signal.store(signal);
    return;
  }
  remove_unfinished_files();
  die_by(signal);
}

}  // namespace

void note_stop_signals() {
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction current {};
    if (sigaction(signal, nullptr, &current) != 0 || current.sa_handler == SIG_IGN) continue;
    struct sigaction noting {};
    noting.sa_handler = on_stop_signal;
    sigemptyset(&noting.sa_mask);  // a SIGTERM does not cut short a second SIGINT's removal
    sigaddset(&noting.sa_mask, SIGINT);
    sigaddset(&noting.sa_mask, SIGTERM);
    noting.sa_flags = SA_RESTART;  // writes carry on
    sigaction(signal, &noting, nullptr);
  }
}

int stop_signal() { return noted_signal.load(); }

RunStopped stopped_by(int signal, const std::string& where, const std::string& when) {
  const char* what = signal == SIGINT ? "interrupted " : "terminated ";
  return RunStopped(where + ": " + what + when, exit_signalled + signal);
}

void ignore_file_size_signal() { std::signal(SIGXFSZ, SIG_IGN); }

}  // namespace lamina::cli
