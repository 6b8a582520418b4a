#include "app/cli/scene_source.h"

#include <filesystem>

#include "scene/builtin_scenes.h"
#include "scene/scene_json.h"

namespace lamina::cli {
namespace {

// A file that is there, or a name that looks like one; a folder that happens to share a built-in
// scene's name (an output folder in the current directory) does not hide the built-in.
bool names_a_file(const std::string& source) {
  const std::filesystem::path path(source);
  std::error_code ignored;
  return (std::filesystem::exists(path, ignored) && !std::filesystem::is_directory(path, ignored)) ||
         path.extension() == ".json" || source.find('/') != std::string::npos;
}

}  // namespace

Scene load_scene(const std::string& source) {
  return names_a_file(source) ? read_scene_file(source) : builtin_scene(source);
}

}  // namespace lamina::cli
