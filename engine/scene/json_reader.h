// The scene reader's tools (scene_json.cpp): a walker of a parsed JSON document that knows where
// it is and throws one SceneError line per problem, and the parser's check for duplicate keys.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "kinematics/math_types.h"
#include "scene/scene_limits.h"

namespace lamina {

// Walks a JSON document, knowing where it is, and throws one SceneError line per problem:
// "<origin>: <path>: <what>", the path written "bodies[2].angle".
class JsonReader {
 public:
  using json = nlohmann::json;

  explicit JsonReader(std::string origin) : origin_(std::move(origin)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const;

  void object(const json& j, const std::string& path) const;
  // An object whose keys are all in `allowed`.
  void expect_object(const json& j, const std::string& path,
                     const std::set<std::string>& allowed) const;
  // A finite number.
  double number(const json& j, const std::string& path) const;
  double in_range(const json& j, const std::string& path, scene_limits::Range<double> range) const;
  // A whole number in the range.
  int count(const json& j, const std::string& path, scene_limits::Range<int> range) const;
  bool boolean(const json& j, const std::string& path) const;
  std::string text(const json& j, const std::string& path) const;
  // An array, of `size` elements unless size is 0.
  const json& array(const json& j, const std::string& path, size_t size) const;
  // A vector whose components each lie in the range.
  Vec2 vec2(const json& j, const std::string& path, scene_limits::Range<double> range) const;
  // obj[key], or a failure "is missing" followed by `hint`.
  const json& required(const json& obj, const std::string& path, const char* key,
                       const std::string& hint = "") const;

  // "bodies[2]" and "angle" make "bodies[2].angle"; "bodies" and 2 make "bodies[2]". `path` is
  // taken by value so that a long path can be moved in and grown in place.
  static std::string join(std::string path, const std::string& key);
  static std::string at(std::string path, size_t index);
  // "a, b, c": keys for messages.
  static std::string list(const std::set<std::string>& keys);

 private:
  static std::string type_of(const json& j);

  std::string origin_;
};

// nlohmann-json keeps the last of two equal keys in an object, so a file with "angle" twice in a
// body would run with one of them silently dropped. The parser reports each step of its reading
// here (json::parse's callback), and a key its object has already is refused. The objects and
// arrays open at that point are kept in a vector, never on the call stack: a file may nest
// 150 000 arrays (see JsonReader::count).
class DuplicateKeys {
 public:
  explicit DuplicateKeys(const JsonReader& reader) : reader_(reader) {}

  void on(nlohmann::json::parse_event_t event, const nlohmann::json& parsed);

 private:
  struct Level {
    bool is_object;
    std::set<std::string> keys;  // an object's keys so far
    std::string key;             // an object's latest key
    size_t elements;             // an array's elements so far
  };

  // A value begins; in an array it is the next element.
  void start_value();
  // The path of the latest key, written as the JsonReader writes paths: "joints[0].anchor".
  std::string path() const;

  const JsonReader& reader_;
  std::vector<Level> levels_;  // the open objects and arrays, outermost first
};

}  // namespace lamina
