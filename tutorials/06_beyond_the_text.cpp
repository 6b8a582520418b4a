// Chapter 6 — beyond the text. The text's PGS is where engines started; this chapter runs the
// methods that came after it (engine/beyond/) on the scenes that break PGS, beside Box2D 2.4.1:
//   table                 who holds what, 60 Hz, 10 s: the table of docs/ch6-beyond-the-text.md,
//                         regenerated (solver_table.md, .csv) and shown as a frame;
//   heavy_on_light_100 …  each scene of the table, every contender's run overlaid (ch6/overlay),
//   pyramid_20            with its plot over time;
//   lambda_error          one step's λ after n sweeps of PGS and of the block solver, against
//                         the exact λ of Lemke's pivoting (ch6/sweeps);
//   pitfall_…             each classic mistake of motion/pitfalls.h put back, beside the same
//                         run without it (ch6/overlay), with its plot.
// Every run of the table is simulated once (ch6/lab) and drawn from what it recorded.
#include <memory>
#include <string>
#include <vector>

#include "app/harness/tutorial.h"
#include "beyond/methods.h"
#include "ch6/lab.h"
#include "ch6/overlay.h"
#include "ch6/sweeps.h"
#include "language/language.h"

namespace {

using namespace lamina;

// The table as a frame: contenders down, scenes across, ✓ where the bars of `islands` hold.
class Table : public tutorial::Scene {
 public:
  tutorial::SceneInfo info() const override {
    return {"table", StepSettings().dt, 1, 1, {Vec2(0.0, 0.0), Vec2(16.0, 9.0)}};
  }
  void step() override {}

  void draw(render::Frame& frame) const override {
    frame.caption = tr("Chapter 6 · who holds what: 60 Hz, 10 s, no sleeping (✓: the bars of islands hold)");
    render::Panel table;
    table.corner = render::Corner::top_left;
    table.title = tr("Box2D 2.4.1 (8 / 3 iterations, block solver) and Lamina's methods");
    table.lines = ch6::table_lines();
    frame.panels.push_back(table);
    render::Panel bars;
    bars.corner = render::Corner::bottom_left;
    bars.title = tr("each column: what it measures; ✓ when");
    for (const ch6::TableScene& s : ch6::table_scenes()) {
      bars.lines.push_back(ch6::scene_title(s.scene) + ": " + ch6::shown(s.measure) + "; " +
                           ch6::shown(ch6::bars(s)));
    }
    frame.panels.push_back(bars);
  }

  tutorial::Explanation explain() const override { return {}; }

  void write_data(const std::filesystem::path& folder) const override { ch6::write_table(folder); }
};

}  // namespace

int main(int argc, char** argv) {
  tutorial::TutorialInfo info{
      "06_beyond_the_text",
      "ch6",
      "Chapter 6, beyond the text: the scenes that break PGS (heavy on light, a tall stack, a "
      "ball on a chain, a pyramid) run by Box2D 2.4.1 and every method, overlaid, tabled and "
      "plotted, and λ sweep by sweep against the exact solve",
      {render::Overlay::contacts, render::Overlay::forces}};
  std::vector<tutorial::SceneFactory> scenes = {tutorial::scene<Table>()};
  for (const ch6::TableScene& s : ch6::table_scenes()) {
    scenes.push_back(ch6::overlay_scene([s] { return ch6::table_comparison(s); }));
  }
  scenes.push_back(ch6::sweeps_scene());
  for (const ch6::PitfallDemo& d : ch6::pitfall_demos()) {
    scenes.push_back(ch6::overlay_scene([d] { return ch6::pitfall_comparison(d); }));
  }
  return tutorial::run_tutorial(argc, argv, info, scenes);
}
