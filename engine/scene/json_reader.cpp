#include "scene/json_reader.h"

#include <cmath>

#include "scene/scene_json.h"
#include "scene/shortest_number.h"

namespace lamina {

using json = nlohmann::json;
using scene_limits::Range;

void JsonReader::fail(const std::string& path, const std::string& what) const {
  throw SceneError(origin_ + ": " + (path.empty() ? "(top level)" : path) + ": " + what);
}

void JsonReader::object(const json& j, const std::string& path) const {
  if (!j.is_object()) fail(path, "must be an object, got " + type_of(j));
}

void JsonReader::expect_object(const json& j, const std::string& path,
                               const std::set<std::string>& allowed) const {
  object(j, path);
  for (const auto& item : j.items()) {
    if (allowed.count(item.key()) == 0) {
      fail(join(path, item.key()), "unknown key (allowed: " + list(allowed) + ")");
    }
  }
}

double JsonReader::number(const json& j, const std::string& path) const {
  if (!j.is_number()) fail(path, "must be a number, got " + type_of(j));
  const double value = j.get<double>();
  if (!std::isfinite(value)) fail(path, "must be finite, got " + j.dump());
  return value;
}

double JsonReader::in_range(const json& j, const std::string& path, Range<double> range) const {
  const double value = number(j, path);
  if (value < range.low || value > range.high) {
    fail(path, "must be in [" + shortest_number(range.low) + ", " + shortest_number(range.high) +
                   "], got " + shortest_number(value));
  }
  return value;
}

int JsonReader::count(const json& j, const std::string& path, Range<int> range) const {
  if (!j.is_number_integer()) {
    // An array or object is named by its type: dumping a deeply nested one overflows the stack.
    const std::string got = j.is_structured() ? std::string(j.type_name()) : j.dump();
    fail(path, "must be a whole number, got " + got);
  }
  const auto value = j.get<long long>();
  if (value < range.low || value > range.high) {
    fail(path, "must be in [" + std::to_string(range.low) + ", " + std::to_string(range.high) +
                   "], got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

bool JsonReader::boolean(const json& j, const std::string& path) const {
  if (!j.is_boolean()) fail(path, "must be true or false, got " + type_of(j));
  return j.get<bool>();
}

std::string JsonReader::text(const json& j, const std::string& path) const {
  if (!j.is_string()) fail(path, "must be a string, got " + type_of(j));
  return j.get<std::string>();
}

const JsonReader::json& JsonReader::array(const json& j, const std::string& path, size_t size) const {
  if (!j.is_array()) fail(path, "must be an array, got " + type_of(j));
  if (size != 0 && j.size() != size) {
    fail(path, "must have " + std::to_string(size) + " elements, got " + std::to_string(j.size()));
  }
  return j;
}

Vec2 JsonReader::vec2(const json& j, const std::string& path, Range<double> range) const {
  array(j, path, 2);
  return {in_range(j[0], at(path, 0), range), in_range(j[1], at(path, 1), range)};
}

const JsonReader::json& JsonReader::required(const json& obj, const std::string& path, const char* key,
                                              const std::string& hint) const {
  if (!obj.contains(key)) fail(join(path, key), "is missing" + hint);
  return obj.at(key);
}

std::string JsonReader::join(std::string path, const std::string& key) {
  if (!path.empty()) path += '.';
  path += key;
  return path;
}

std::string JsonReader::at(std::string path, size_t index) {
  path += "[" + std::to_string(index) + "]";
  return path;
}

std::string JsonReader::list(const std::set<std::string>& keys) {
  std::string out;
  for (const std::string& key : keys) out += (out.empty() ? "" : ", ") + key;
  return out;
}

std::string JsonReader::type_of(const json& j) {
  return j.is_number() ? "number " + j.dump() : std::string(j.type_name());
}

void DuplicateKeys::on(json::parse_event_t event, const json& parsed) {
  switch (event) {
    case json::parse_event_t::object_start:
    case json::parse_event_t::array_start:
      start_value();
      levels_.push_back({event == json::parse_event_t::object_start, {}, {}, 0});
      break;
    case json::parse_event_t::key: {
      Level& object = levels_.back();
      object.key = parsed.get<std::string>();
      if (!object.keys.insert(object.key).second) {
        reader_.fail(path(), "duplicate key: the object has \"" + object.key + "\" already");
      }
      break;
    }
    case json::parse_event_t::object_end:
    case json::parse_event_t::array_end:
      levels_.pop_back();
      break;
    case json::parse_event_t::value:
      start_value();
      break;
  }
}

void DuplicateKeys::start_value() {
  if (!levels_.empty() && !levels_.back().is_object) ++levels_.back().elements;
}

std::string DuplicateKeys::path() const {
  std::string p;
  for (const Level& level : levels_) {
    p = level.is_object ? JsonReader::join(std::move(p), level.key)
                        : JsonReader::at(std::move(p), level.elements - 1);
  }
  return p;
}

}  // namespace lamina
