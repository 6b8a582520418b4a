// lamina: run, list, show and check scenes (docs/lamina-command.md).
//
// Every failure is one line on standard error, "lamina: <what, where>", and its exit code says
// what happened: 2 for input the user can fix, 3 for a run that diverged, 128 + the signal for a
// run stopped by Ctrl-C or SIGTERM, 1 for anything else.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

#include "app/cli/command_line.h"
#include "app/cli/exit_codes.h"
#include "app/cli/scene_commands.h"
#include "app/cli/signals.h"
#include "output/output_file.h"
#include "scene/scene_json.h"

namespace {

using namespace lamina::cli;

void execute(const Command& c) {
  switch (c.kind) {
    case Command::Kind::run: return run_scene(c.run);
    case Command::Kind::scenes: return list_scenes();
    case Command::Kind::solvers: return list_solvers();
    case Command::Kind::show: return show_scene(c.scene);
    case Command::Kind::check: return check_scene(c.scene);
  }
}

// What went to standard output reached it (not a full disk, not past `ulimit -f`).
void flush_standard_output() {
  std::cout.flush();
  if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0 || !std::cout) {
    throw lamina::OutputError(std::string("cannot write standard output: ") + std::strerror(errno));
  }
}

int failed(const std::exception& e, int code) {
  std::cerr << "lamina: " << e.what() << '\n';
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  ignore_file_size_signal();
  const ParsedCommand parsed = parse_command_line(argc, argv);
  if (!parsed.command) return parsed.exit_code;
  try {
    execute(*parsed.command);
    flush_standard_output();
    return exit_ok;
  } catch (const RunStopped& e) {
    return failed(e, e.exit_code());
  } catch (const lamina::SceneError& e) {
    return failed(e, exit_bad_input);
  } catch (const InputError& e) {
    return failed(e, exit_bad_input);
  } catch (const lamina::OutputError& e) {
    return failed(e, exit_bad_input);
  } catch (const std::exception& e) {
    return failed(e, exit_internal_failure);
  }
}
