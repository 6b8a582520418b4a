// Runs of one scene drawn on one picture: each run's moving bodies translucent in its own
// colour (the legend names them), the static bodies once in grey, and a panel with the largest
// value each run has reached so far of what the comparison follows. Its plot over time of that
// value (and, for a scene with joints, of the energy) is written beside the frames. Chapter 6
// compares every contender on each scene of the table, and each pitfall with the engine as it is.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/harness/tutorial.h"
#include "ch6/lab.h"
#include "scene/scene.h"

namespace lamina::ch6 {

struct Comparison {
  std::string stem;                   // the frames' and plot's file stem
  std::string caption;                // the frames' caption
  lamina::Scene scene;                // its bodies' shapes, which are static, its Δt
  lamina::Scene explained;            // what --explain K steps: the scene by one method
  render::Rect view;                  // the least region the frames show, in m
  double headroom = 0.0;              // added above the bodies' highest reach, in m (for a panel)
  std::vector<Contender> who;         // one per run: its name and colour
  std::function<const std::vector<LabRun>&()> runs;  // the runs, simulated once
  std::string measure;                // what the panel and plot follow, with its unit
  std::function<double(const LabSample&)> followed;  // its value at a sample
  bool log_plot = false;              // a log y axis, values below `floor` (1 µm) drawn at it
  double floor = 0.0;                 // 1 µm in the measure's unit
  std::string legend = "top right";   // where the plot's legend sits
};

// `make` is called when the scene is made, after the options have set the language: the
// comparison's captions, measure and names are in the frames' language.
tutorial::SceneFactory overlay_scene(std::function<Comparison()> make);

// Each scene of the table, every contender's run of it.
Comparison table_comparison(const TableScene& scene);
// A pitfall's demonstration: the engine as it is beside the same run with the pitfall.
Comparison pitfall_comparison(const PitfallDemo& demo);

}  // namespace lamina::ch6
