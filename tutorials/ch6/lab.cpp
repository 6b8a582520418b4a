#include "ch6/lab.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "app/harness/format.h"
#include "app/reference/box2d_lab.h"
#include "beyond/methods.h"
#include "language/language.h"
#include "scene/builtin_scenes.h"
#include "output/output_file.h"

namespace lamina::ch6 {
namespace {

using tutorial::fixed;

std::string mm(double metres) { return fixed(1000.0 * metres, 1); }

// Whether the run meets the bars of Lamina's own method on the scene (the issue's, 60 Hz, 10 s).
bool meets_bars(const TableScene& scene, const LabRun& r) {
  if (r.diverged) return false;
  if (scene.scene == "heavy-on-light:100") return r.deepest <= 0.010 && r.sideways <= 0.005;
  if (scene.scene == "heavy-on-light:1000") return r.deepest <= 0.020;
  if (scene.scene == "vertical-stack:20") return r.top_sway <= 0.010 && std::abs(r.top_rise) <= 0.020;
  if (scene.scene == "ball-and-chain:100") return r.stretch <= 0.01;
  return r.samples.back().top <= 0.2 && r.sideways <= 0.1;  // pyramid:20
}

// The run's numbers for the scene's column.
std::string numbers(const TableScene& scene, const LabRun& r) {
  if (r.diverged) return "diverged";
  if (scene.scene.rfind("heavy-on-light", 0) == 0) return mm(r.deepest) + " / " + mm(r.sideways);
  if (scene.scene == "vertical-stack:20") return mm(r.top_sway) + " / " + mm(r.top_rise);
  if (scene.scene == "ball-and-chain:100") return fixed(100.0 * r.stretch, 2);
  return fixed(r.samples.back().top, 3) + " / " + fixed(r.sideways, 3);
}

}  // namespace

const std::vector<TableScene>& table_scenes() {
  static const std::vector<TableScene> list = {
      {"heavy-on-light:100", "heavy_on_light_100", {Vec2(-2.2, -0.4), Vec2(2.2, 2.4)},
       msg("overlap / sideways (mm)")},
      {"heavy-on-light:1000", "heavy_on_light_1000", {Vec2(-2.2, -0.4), Vec2(2.2, 2.4)},
       msg("overlap / sideways (mm)")},
      {"vertical-stack:20", "vertical_stack_20", {Vec2(-7.0, -0.5), Vec2(7.0, 21.5)},
       msg("top sway / top height change (mm)")},
      {"ball-and-chain:100", "ball_and_chain_100", {Vec2(-6.5, -0.5), Vec2(6.5, 11.0)},
       msg("largest stretch (%)")},
      {"pyramid:20", "pyramid_20", {Vec2(-11.0, -0.5), Vec2(11.0, 21.5)},
       msg("apex moved / any box sideways (m)")},
  };
  return list;
}

const std::vector<Contender>& contenders() {
  static const std::vector<Contender> list = [] {
    const std::map<std::string, render::Colour> colours = {
        {"text", render::palette::vermillion},   {"pgs", render::palette::orange},
        {"block", render::palette::reddish_purple}, {"exact", render::palette::sky_blue},
        {"soft-step", render::palette::grey},    {"islands", render::palette::bluish_green}};
    std::vector<Contender> all = {{box2d_name, render::palette::blue}};
    for (const SolverInfo& m : method_list()) all.push_back({m.name, colours.at(m.name)});
    return all;
  }();
  return list;
}

const std::vector<LabRun>& lab_runs(const TableScene& scene) {
  static std::map<std::string, std::vector<LabRun>> runs;
  std::vector<LabRun>& found = runs[scene.scene];
  if (found.empty()) {
    for (const Contender& c : contenders()) {
      found.push_back(c.name == box2d_name ? run_box2d_lab(scene.scene, lab_steps)
                                           : run_lab(scene.scene, c.name, lab_steps));
    }
  }
  return found;
}

const std::vector<PitfallDemo>& pitfall_demos() {
  const render::Rect stack{Vec2(-3.0, -0.5), Vec2(3.0, 5.8)};
  static const std::vector<PitfallDemo> list = {
      {Pitfall::lambda_b1, "vertical-stack:5", "pgs", "lambda_b1", stack, msg("top box moved (m)")},
      {Pitfall::no_renormalisation, "spinning-box", "pgs", "no_renormalisation",
       {Vec2(-3.0, -0.5), Vec2(3.0, 5.0)}, msg("box moved (m)")},
      {Pitfall::clamp_increment, "vertical-stack:5", "pgs", "clamp_increment", stack, msg("top box moved (m)")},
      {Pitfall::no_warm_start, "vertical-stack:5", "pgs", "no_warm_start", stack, msg("top box moved (m)")},
      {Pitfall::crude_friction, "friction-ramp", "pgs", "crude_friction",
       {Vec2(-9.5, -5.8), Vec2(9.5, 6.0)}, msg("box moved (m)")},
      {Pitfall::baumgarte_no_slop, "vertical-stack:5", "pgs", "baumgarte_no_slop", stack,
       msg("top box moved (m)")},
  };
  return list;
}

Scene demo_scene(const PitfallDemo& demo) {
  Scene scene;
  if (demo.scene == "spinning-box") {
    scene = builtin_scene("box-on-ground");
    scene.name = "spinning-box";
    scene.description = "a unit box thrown up at 4 m/s from y = 3, turning at 20 rad/s";
    BodyDescription& box = scene.bodies.back();
    box.position = {0.0, 3.0};
    box.velocity = {0.0, 4.0};
    box.angular_velocity = 20.0;
  } else {
    scene = builtin_scene(demo.scene);
  }
  scene.solver = demo.method;
  return scene;
}

const std::vector<LabRun>& pitfall_runs(const PitfallDemo& demo) {
  static std::map<std::string, std::vector<LabRun>> runs;
  std::vector<LabRun>& found = runs[demo.stem];
  if (found.empty()) {
    Scene scene = demo_scene(demo);
    found.push_back(run_lab(scene, lab_steps));
    scene.step.pitfalls.add(demo.pitfall);
    found.push_back(run_lab(scene, lab_steps));
  }
  return found;
}

std::string table_cell(const TableScene& scene, const LabRun& run, bool shown) {
  return std::string(meets_bars(scene, run) ? "✓ " : "✗ ") +
         (shown && run.diverged ? std::string(tr("diverged")) : numbers(scene, run));
}

std::string bars(const TableScene& scene) {
  if (scene.scene == "heavy-on-light:100") return msg("overlap ≤ 10 mm, no box 5 mm sideways");
  if (scene.scene == "heavy-on-light:1000") return msg("overlap ≤ 20 mm");
  if (scene.scene == "vertical-stack:20") return msg("top sways ≤ 10 mm, ends within 20 mm of its height");
  if (scene.scene == "ball-and-chain:100") return msg("pin to ball ≤ 1 % past its rest length");
  return msg("apex within 0.2 m, no box 0.1 m sideways");
}

std::string scene_title(const std::string& scene) {
  // the names of the scenes the lab shows, as messages (their Korean in ch6.po)
  static const char* const names[] = {msg("heavy-on-light"), msg("vertical-stack"),
                                      msg("ball-and-chain"),  msg("pyramid"),
                                      msg("spinning-box"),    msg("friction-ramp")};
  const std::string family = scene.substr(0, scene.find(':'));
  for (const char* name : names) {
    if (family == name) return tr(name) + scene.substr(family.size());
  }
  return scene;
}

std::string shown(const std::string& english) { return tr(english.c_str()); }

namespace {

std::size_t text_width(const std::string& s) {
  // in a monospaced face's cells: count UTF-8 lead bytes, not bytes (✓, ✗ are three bytes
  // each), and a Hangul syllable (U+AC00..U+D7A3, lead byte 0xEA..0xED) as two cells
  std::size_t cells = 0;
  for (const char c : s) {
    const unsigned char b = static_cast<unsigned char>(c);
    if ((b & 0xC0) != 0x80) cells += b >= 0xEA && b <= 0xED ? 2 : 1;
  }
  return cells;
}

}  // namespace

std::vector<std::string> table_lines() {
  const std::size_t name_width = 13, cell_width = 21;
  auto pad = [](std::string s, std::size_t width) {
    const std::size_t cells = text_width(s);
    if (cells < width) s += std::string(width - cells, ' ');
    return s;
  };
  std::vector<std::string> lines(2);
  lines[0] = pad("", name_width);
  for (const TableScene& s : table_scenes()) lines[0] += pad(scene_title(s.scene), cell_width);
  for (std::size_t c = 0; c < contenders().size(); ++c) {
    std::string line = pad(contenders()[c].name, name_width);
    for (const TableScene& s : table_scenes()) line += pad(table_cell(s, lab_runs(s)[c], true), cell_width);
    lines.push_back(line);
  }
  return lines;
}

void write_table(const std::filesystem::path& folder) {
  std::ostringstream md, csv;
  csv.precision(9);
  md << "| scene (measure; bar of `islands`) |";
  for (const Contender& c : contenders()) md << " " << c.name << " |";
  md << "\n|---|";
  for (std::size_t c = 0; c < contenders().size(); ++c) md << "---|";
  md << "\n";
  csv << "scene,contender,meets_bars,deepest_overlap_m,largest_sideways_m,top_sway_m,top_rise_m,"
         "largest_stretch,diverged\n";
  for (const TableScene& s : table_scenes()) {
    md << "| " << s.scene << " (" << s.measure << "; " << bars(s) << ") |";
    const std::vector<LabRun>& runs = lab_runs(s);
    for (std::size_t c = 0; c < runs.size(); ++c) {
      const LabRun& r = runs[c];
      md << " " << table_cell(s, r) << " |";
      csv << s.scene << "," << contenders()[c].name << "," << meets_bars(s, r) << "," << r.deepest
          << "," << r.sideways << "," << r.top_sway << "," << r.top_rise << "," << r.stretch << ","
          << r.diverged << "\n";
    }
    md << "\n";
  }
  write_file_atomically(folder / "solver_table.md", md.str());
  write_file_atomically(folder / "solver_table.csv", csv.str());
  // The cost, apart: timings differ from run to run, the table does not.
  std::ostringstream cost;
  cost << "| scene (ms per step, × Box2D's; the MLCP's rows per step) |";
  for (const Contender& c : contenders()) cost << " " << c.name << " |";
  cost << "\n|---|";
  for (std::size_t c = 0; c < contenders().size(); ++c) cost << "---|";
  cost << "\n";
  for (const TableScene& s : table_scenes()) {
    const std::vector<LabRun>& runs = lab_runs(s);
    cost << "| " << s.scene << " |";
    for (const LabRun& r : runs) {
      cost << " " << fixed(r.ms_per_step, 3) << " (" << fixed(r.ms_per_step / runs[0].ms_per_step, 2) << "×)";
      if (r.rows_per_step > 0.0) cost << ", " << fixed(r.rows_per_step, 0) << " rows";
      cost << " |";
    }
    cost << "\n";
  }
  write_file_atomically(folder / "solver_cost.md", cost.str());
}

}  // namespace lamina::ch6
