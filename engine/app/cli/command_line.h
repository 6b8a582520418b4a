// lamina's command line (CLI11): the four subcommands, their options and their --help.
#pragma once

#include <optional>
#include <string>

#include "app/cli/run_command.h"

namespace lamina::cli {

struct Command {
  enum class Kind { run, scenes, solvers, show, check };
  Kind kind = Kind::run;
  RunOptions run;     // run's options
  std::string scene;  // show's and check's SCENE
};

// The command, or the exit code when parsing ended the run: 0 after --help, exit_bad_input
// after one line naming a bad option or value.
struct ParsedCommand {
  std::optional<Command> command;
  int exit_code = 0;
};

ParsedCommand parse_command_line(int argc, char** argv);

}  // namespace lamina::cli
