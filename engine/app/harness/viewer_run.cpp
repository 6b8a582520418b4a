// --viewer DIR of a tutorial: each scene stepped over the span its frames cover, every step
// recorded, then one page for all of them.
#include <cstdio>

#include "app/harness/runs.h"
#include "app/harness/viewer.h"

namespace lamina::tutorial {

void view_scenes(const TutorialInfo& info, const Options& o, const std::vector<SceneFactory>& scenes) {
  RenderRequest request = o.render;
  request.out = *o.viewer;
  ViewerPage page(request);  // the folder, before any step
  std::vector<ViewerRun> runs;
  for (const SceneFactory& make : scenes) {
    const auto scene = make(o);
    const SceneInfo s = scene->info();
    const long last = static_cast<long>(o.frames.value_or(s.frames) - 1) * o.every.value_or(s.every);
    ViewerRun& run = runs.emplace_back(info.name, s.name, s.time_step, ViewerLimits{o.viewer_steps});
    run.fit(s.view);
    // step k shows what the tutorial draws after k steps, and explains the step that led there
    // (the initial state at k = 0), as its frames and --explain k do
    for (long k = 0; k <= last; ++k) {
      if (k > 0) scene->step();
      ViewerStep step;
      scene->record(step);
      // a scene that records its step brings its explanation with it; one explanation a step
      if (step.phases.empty()) step.phases = scene->explain();
      render::Frame frame;
      scene->draw(frame);
      run.add(step, std::move(frame));
    }
  }
  page.write(runs);
  for (const ViewerRun& run : runs) {
    const auto detailed = run.detailed();
    std::printf("%s: viewer of %s, %ld steps (rows and sweeps of %s) -> %s\n", info.name.c_str(),
                run.scene().c_str(), run.steps(),
                detailed ? ("steps " + std::to_string((*detailed)[0]) + ".." + std::to_string((*detailed)[1])).c_str()
                         : "no step",
                (*o.viewer / "index.html").c_str());
  }
}

}  // namespace lamina::tutorial
