// `lamina scenes`, `lamina solvers`, `lamina show SCENE` and `lamina check SCENE`: the scenes and
// the methods, without running them.
#pragma once

#include <string>

namespace lamina::cli {

// The built-in scenes, one per line: name, then its one-line description.
void list_scenes();

// The solvers, one per line: name, then what it does and departs from the text.
void list_solvers();

// The scene as a JSON scene file on standard output (docs/scene-format.md).
void show_scene(const std::string& source);

// Reads and validates the scene and builds its world; prints one line saying it is fine.
// Throws SceneError or InputError naming the problem.
void check_scene(const std::string& source);

}  // namespace lamina::cli
