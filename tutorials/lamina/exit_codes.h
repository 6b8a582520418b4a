// lamina's exit codes (docs/lamina-command.md) and the error that means "bad input".
#pragma once

#include <stdexcept>

namespace lamina::cli {

enum ExitCode : int {
  exit_ok = 0,
  exit_internal_failure = 1,  // a bug or the machine (no OpenGL): not the user's input
  exit_bad_input = 2,         // a bad scene, option value or output path
};

// Input the user can fix (a scene the engine refuses, a bad option value): one line naming it.
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace lamina::cli
