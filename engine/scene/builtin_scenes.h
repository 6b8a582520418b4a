// The built-in scenes that tutorials, tests and benchmarks share, by name.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace lamina {

struct BuiltinScene {
  std::string name;         // what `lamina run NAME` takes
  std::string description;  // one line for `lamina scenes`
};

// Every built-in scene's name and description, in order of name; read from a table, building
// no scene.
std::vector<BuiltinScene> builtin_scene_list();

// The built-in scene of that name, with the list's description; "pyramid:N" gives a pyramid of
// N rows. Throws SceneError for an unknown name.
Scene builtin_scene(const std::string& name);

// A pyramid of boxes (half extents 0.5, placed touching) with `rows` boxes in its base.
Scene pyramid_scene(int rows);

}  // namespace lamina
