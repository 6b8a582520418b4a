// lamina: run, list, show and check scenes (docs/lamina-command.md).
//
// Every failure is one line on standard error, "lamina: <what, where>", and its exit code says
// whose it is: 2 for input the user can fix, 1 for anything else.
#include <exception>
#include <iostream>

#include "lamina/command_line.h"
#include "lamina/exit_codes.h"
#include "lamina/scene_commands.h"
#include "render/safe_file.h"
#include "scene/output_file.h"
#include "scene/scene_json.h"

namespace {

using namespace lamina::cli;

void execute(const Command& c) {
  switch (c.kind) {
    case Command::Kind::run: return run_scene(c.run);
    case Command::Kind::scenes: return list_scenes();
    case Command::Kind::show: return show_scene(c.scene);
    case Command::Kind::check: return check_scene(c.scene);
  }
}

int failed(const std::exception& e, ExitCode code) {
  std::cerr << "lamina: " << e.what() << '\n';
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  const ParsedCommand parsed = parse_command_line(argc, argv);
  if (!parsed.command) return parsed.exit_code;
  try {
    execute(*parsed.command);
    return exit_ok;
  } catch (const lamina::SceneError& e) {
    return failed(e, exit_bad_input);
  } catch (const InputError& e) {
    return failed(e, exit_bad_input);
  } catch (const lamina::OutputFileError& e) {
    return failed(e, exit_bad_input);
  } catch (const lamina::render::OutputError& e) {
    return failed(e, exit_bad_input);
  } catch (const std::exception& e) {
    return failed(e, exit_internal_failure);
  }
}
