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

// A family of built-in scenes with one parameter, `NAME:P` (`pyramid:20`, `heavy-on-light:100`);
// `NAME` alone is the family's default member.
struct SceneFamily {
  std::string name;         // "pyramid"
  std::string parameter;    // "N" or "R", as `lamina scenes` shows it
  std::string description;  // one line: what P is, its range and its default
};

// Every built-in scene's name and description, in order of name; read from a table, building
// no scene. A family's default member is listed under the family's name.
std::vector<BuiltinScene> builtin_scene_list();

// The families of parameterised scenes, in order of name.
std::vector<SceneFamily> builtin_scene_families();

// The built-in scene of that name, with the list's description; "NAME:P" gives a family's member
// (builtin_scene_families). Throws SceneError for an unknown name or a parameter out of range.
Scene builtin_scene(const std::string& name);

// The scene's description as a frame shows it: a built-in scene's (its description unchanged) in
// the current language (language.h), any other as written.
std::string shown_description(const Scene& scene);

// A pyramid of boxes (half extents 0.5, placed touching) with `rows` boxes in its base.
Scene pyramid_scene(int rows);

}  // namespace lamina
