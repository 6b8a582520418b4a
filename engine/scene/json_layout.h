// Scene files as written (scene_to_json, `lamina show`): the scene as a JSON document with every
// key, defaults included, in a fixed order (name first), laid out for people to read and edit:
// a value that fits on its line within `width` columns is written on one line,
// {"type": "box", "half_extents": [0.5, 0.5]}; any other array or object has one element per
// line, indented by two spaces. Numbers are nlohmann-json's shortest round-trip form, so the text
// reads back exactly.
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace lamina {

// A joint type's name in a scene file: "revolute", "distance", "angle_limit" or "incline".
const char* joint_type_name(JointType type);

// The scene as a document that parse_scene reads back to the same scene.
nlohmann::ordered_json scene_document(const Scene& scene);

std::string layout_json(const nlohmann::ordered_json& value, std::size_t width = 100);

}  // namespace lamina
