// Scene files: JSON in, JSON out, validated strictly at the boundary.
//
// Every problem is reported as one SceneError line: "<file>: <JSON path>: <what is wrong>",
// e.g. "box.json: bodies[1].shape.half_extents[0]: must be positive, got -1".
#pragma once

#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace lamina {

class SceneError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Parses and validates a scene; `origin` names the source in messages (a file path).
Scene parse_scene(const std::string& json_text, const std::string& origin);

// Reads and validates a scene file.
Scene read_scene_file(const std::string& path);

// The scene as a JSON document (two-space indent) that parse_scene reads back to the same scene.
std::string scene_to_json(const Scene& scene);

}  // namespace lamina
