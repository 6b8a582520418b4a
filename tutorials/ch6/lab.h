// Chapter 6's table, simulated once per run of 06_beyond_the_text: each scene of the table run
// for 10 s at 60 Hz by each contender (Box2D 2.4.1 in this process, and every Lamina method),
// measured by app/views/beyond/solver_lab.h, judged against the bars of Lamina's own method
// (docs/ch6-beyond-the-text.md), and written as solver_table.md / .csv.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/views/beyond/solver_lab.h"
#include "motion/pitfalls.h"
#include "render/camera.h"
#include "render/colour.h"
#include "scene/scene.h"

namespace lamina::ch6 {

constexpr int lab_steps = 600;  // 10 s at Δt = 1/60 s

// A scene of the table: the built-in scene, the stem of its files, the region its frames show,
// and what its column measures.
struct TableScene {
  std::string scene;    // e.g. "heavy-on-light:1000"
  std::string stem;     // e.g. "heavy_on_light_1000"
  render::Rect view;    // in m
  std::string measure;  // the column's heading, with units
};
const std::vector<TableScene>& table_scenes();

// Who runs the scenes: Box2D 2.4.1, then Lamina's methods in `lamina solvers` order.
struct Contender {
  std::string name;  // box2d_name or a method
  render::Colour colour;
};
const std::vector<Contender>& contenders();

// The runs of the scene by every contender, in contenders() order; simulated on first use and
// kept for the rest of the process.
const std::vector<LabRun>& lab_runs(const TableScene& scene);

// A run's cell of the table: "✓" or "✗" against the scene's bars, then its numbers; `shown`:
// as a frame shows it, in the frame's language (solver_table.md keeps the English).
std::string table_cell(const TableScene& scene, const LabRun& run, bool shown = false);
// The bars of Lamina's own method on the scene, in words (English, as solver_table.md has them).
std::string bars(const TableScene& scene);

// A built-in scene's name (NAME or NAME:P) as a frame or plot shows it, in the frame's language.
std::string scene_title(const std::string& scene);
// One of this file's English texts (a column's measure, a scene's bars, a demo's measure) in the
// frame's language.
std::string shown(const std::string& english);

// A pitfall (motion/pitfalls.h) shown on a scene where it breaks what the engine holds: the
// same run with and without it.
struct PitfallDemo {
  Pitfall pitfall;
  std::string scene;    // a built-in scene, or "spinning-box" (demo_scene)
  std::string method;   // the method both runs step with
  std::string stem;     // the files' stem
  render::Rect view;    // the least region the frames show
  std::string measure;  // what the panel and plot follow: LabSample::top, named
};
const std::vector<PitfallDemo>& pitfall_demos();
// The demo's scene, by its method: a built-in one, or the spinning box (a unit box thrown up at
// 4 m/s from y = 3 turning at 20 rad/s over the ground).
Scene demo_scene(const PitfallDemo& demo);
// [the run as it is, the run with the pitfall], simulated on first use and kept.
const std::vector<LabRun>& pitfall_runs(const PitfallDemo& demo);

// The table as lines of text, contenders down, scenes across (for a frame's panel).
std::vector<std::string> table_lines();
// folder/solver_table.md and folder/solver_table.csv; and folder/solver_cost.md, each run's CPU
// time per step (stepping and measuring alike) and its ratio to Box2D's on the same scene in
// the same run, apart from the table because timings vary from run to run.
void write_table(const std::filesystem::path& folder);

}  // namespace lamina::ch6
