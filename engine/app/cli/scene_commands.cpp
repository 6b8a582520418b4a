#include "app/cli/scene_commands.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "app/cli/scene_source.h"
#include "app/harness/format.h"
#include "app/cli/simulation.h"
#include "beyond/methods.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_json.h"
#include "scene/scene_world.h"

namespace lamina::cli {

void list_solvers() {
  std::size_t width = 0;
  for (const SolverInfo& s : method_list()) width = std::max(width, s.name.size());
  for (const SolverInfo& s : method_list()) {
    std::printf("%-*s  %s\n", static_cast<int>(width), s.name.c_str(), s.departures.c_str());
  }
}

void list_scenes() {
  const std::vector<BuiltinScene> scenes = builtin_scene_list();
  std::vector<BuiltinScene> families;
  for (const SceneFamily& f : builtin_scene_families()) {
    families.push_back({f.name + ":" + f.parameter, f.description});
  }
  std::size_t width = 0;
  for (const BuiltinScene& s : scenes) width = std::max(width, s.name.size());
  for (const BuiltinScene& s : families) width = std::max(width, s.name.size());
  for (const std::vector<BuiltinScene>* list : {&scenes, &std::as_const(families)}) {
    for (const BuiltinScene& s : *list) {
      std::printf("%-*s  %s\n", static_cast<int>(width), s.name.c_str(), s.description.c_str());
    }
  }
}

namespace {


}  // namespace

void show_scene(const std::string& source) { std::cout << scene_to_json(load_scene(source)); }

void check_scene(const std::string& source) {
  const Scene scene = load_scene(source);
  checked_world(scene, checked_settings(scene, source), source);
  std::cout << source << ": ok, " << tutorial::counted(static_cast<long>(scene.bodies.size()), "body", "bodies") << ", "
            << tutorial::counted(static_cast<long>(scene.joints.size()), "joint", "joints") << "\n";
}

}  // namespace lamina::cli
