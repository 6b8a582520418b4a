// JSON laid out for people to read and edit (scene files from `lamina show`): a value that fits
// on its line within `width` columns is written on one line, {"type": "box", "half_extents":
// [0.5, 0.5]}; any other array or object has one element per line, indented by two spaces.
// Numbers are nlohmann-json's shortest round-trip form, so the text reads back exactly.
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace lamina {

std::string layout_json(const nlohmann::ordered_json& value, std::size_t width = 100);

}  // namespace lamina
