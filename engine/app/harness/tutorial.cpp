#include "app/harness/tutorial.h"

#include <exception>
#include <iostream>

#include "app/harness/runs.h"
#include "output/output_file.h"

namespace lamina::tutorial {

int run_tutorial(int argc, char** argv, const TutorialInfo& info,
                 const std::vector<SceneFactory>& scenes) {
  const ParsedOptions parsed = parse_options(argc, argv, info);
  if (!parsed.options) return parsed.exit_code;
  const Options& options = *parsed.options;
  try {
    if (options.explain_step || options.step_through) {
      explain_scenes(info, options, scenes);
    } else if (options.viewer) {
      view_scenes(info, options, scenes);
    } else {
      render_scenes(info, options, scenes);
    }
    return 0;
  } catch (const OutputError& e) {
    std::cerr << info.name << ": " << e.what() << '\n';
    return 2;  // an output path that cannot be written: the reader's to mend
  } catch (const std::exception& e) {
    std::cerr << info.name << ": " << e.what() << '\n';
    return 1;
  }
}

}  // namespace lamina::tutorial
