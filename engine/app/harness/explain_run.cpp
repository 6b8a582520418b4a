// Explaining: step the scene, print what it computed, no GL context and no files.
#include <unistd.h>

#include <iostream>
#include <string>

#include "app/harness/runs.h"
#include "language/language.h"

namespace lamina::tutorial {
namespace {

void print(const Options& o, const StepContext& context, const Explanation& explanation) {
  if (o.json) {
    // One object per step: indented for --explain, one line each (JSON Lines) when stepping.
    std::cout << to_json(context, explanation).dump(o.step_through ? -1 : 2) << std::endl;
  } else {
    std::cout << to_text(context, explanation) << std::endl;
  }
}

// Waits for Enter on a terminal; false when the reader typed q (or closed the input).
bool next_step_wanted() {
  if (!isatty(STDIN_FILENO)) return true;
  std::cerr << tr("-- Enter: next step, q: quit -- ") << std::flush;
  std::string line;
  return std::getline(std::cin, line) && line != "q";
}

}  // namespace

void explain_scenes(const TutorialInfo& info, const Options& o,
                    const std::vector<SceneFactory>& scenes) {
  for (const SceneFactory& make : scenes) {
    const auto scene = make(o);
    const SceneInfo s = scene->info();
    const long last = o.explain_step ? *o.explain_step
                                     : static_cast<long>(o.frames.value_or(s.frames) - 1) *
                                           o.every.value_or(s.every);
    for (long step = 0; step <= last; ++step) {
      if (step > 0) scene->step();
      if (step < last && o.explain_step) continue;
      print(o, {info.name, s.name, step, step * s.time_step, s.time_step}, scene->explain());
      if (step < last && !next_step_wanted()) break;
    }
  }
}

}  // namespace lamina::tutorial
