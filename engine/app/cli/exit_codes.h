// lamina's exit codes (docs/lamina-command.md) and the errors that carry them.
#pragma once

#include <stdexcept>
#include <string>

namespace lamina::cli {

enum ExitCode : int {
  exit_ok = 0,
  exit_internal_failure = 1,  // a bug or the machine (no OpenGL): not the user's input
  exit_bad_input = 2,         // a bad scene, option value or output path
  exit_diverged = 3,          // the simulation diverged: a body's state is no longer finite
  exit_signalled = 128,       // plus the signal that stopped the run: 130 Ctrl-C, 143 SIGTERM
};

// Input the user can fix (a scene the engine refuses, a bad option value): one line naming it.
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A run that stopped before its last step (it diverged, or a signal asked it to stop) with its
// outputs complete up to there: one line saying why and what was kept, and the exit code.
class RunStopped : public std::runtime_error {
 public:
  RunStopped(const std::string& what, int exit_code)
      : std::runtime_error(what), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;  // exit_diverged, or exit_signalled + the signal
};

}  // namespace lamina::cli
