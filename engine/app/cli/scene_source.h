// SCENE, as `lamina run`, `show` and `check` take it: a scene file or a built-in scene's name.
#pragma once

#include <string>

#include "scene/scene.h"

namespace lamina::cli {

// A path that exists, ends in ".json" or holds a '/' is read as a scene file; anything else
// is a built-in scene's name ("pyramid:N" included). Throws SceneError naming what is wrong.
Scene load_scene(const std::string& source);

}  // namespace lamina::cli
