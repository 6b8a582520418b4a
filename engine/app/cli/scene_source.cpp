#include "app/cli/scene_source.h"

#include <filesystem>

#include "scene/builtin_scenes.h"
#include "scene/scene_json.h"

namespace lamina::cli {
namespace {

bool names_a_file(const std::string& source) {
  const std::filesystem::path path(source);
  return std::filesystem::exists(path) || path.extension() == ".json" ||
         source.find('/') != std::string::npos;
}

}  // namespace

Scene load_scene(const std::string& source) {
  return names_a_file(source) ? read_scene_file(source) : builtin_scene(source);
}

}  // namespace lamina::cli
