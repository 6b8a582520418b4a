#include "lamina/signals.h"

#include <atomic>
#include <csignal>

#include <signal.h>

namespace lamina::cli {
namespace {

// The signal noted by the handler; lock-free, so safe to set in a handler on any thread.
std::atomic<int> noted_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

void note(int signal) { noted_signal.store(signal); }

}  // namespace

void note_stop_signals() {
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction current {};
    if (sigaction(signal, nullptr, &current) != 0 || current.sa_handler == SIG_IGN) continue;
    struct sigaction noting {};
    noting.sa_handler = note;
    sigemptyset(&noting.sa_mask);
    noting.sa_flags = SA_RESTART | SA_RESETHAND;  // writes carry on; a second signal is fatal
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
