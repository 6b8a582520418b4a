#include "scene/scene_json.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "kinematics/mass_properties.h"
#include "scene/json_layout.h"
#include "scene/scene_limits.h"
#include "scene/shortest_number.h"

namespace lamina {
namespace {

using nlohmann::json;
using scene_limits::Range;

// Walks a JSON document, knowing where it is, and throws one SceneError line per problem.
class Reader {
 public:
  explicit Reader(std::string origin) : origin_(std::move(origin)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw SceneError(origin_ + ": " + (path.empty() ? "(top level)" : path) + ": " + what);
  }

  void object(const json& j, const std::string& path) const {
    if (!j.is_object()) fail(path, "must be an object, got " + type_of(j));
  }

  void expect_object(const json& j, const std::string& path,
                     const std::set<std::string>& allowed) const {
    object(j, path);
    for (const auto& item : j.items()) {
      if (allowed.count(item.key()) == 0) {
        fail(join(path, item.key()), "unknown key (allowed: " + list(allowed) + ")");
      }
    }
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, "must be a number, got " + type_of(j));
    const double value = j.get<double>();
    if (!std::isfinite(value)) fail(path, "must be finite, got " + j.dump());
    return value;
  }

  double in_range(const json& j, const std::string& path, Range<double> range) const {
    const double value = number(j, path);
    if (value < range.low || value > range.high) {
      fail(path, "must be in [" + shortest_number(range.low) + ", " + shortest_number(range.high) +
                     "], got " + shortest_number(value));
    }
    return value;
  }


  int count(const json& j, const std::string& path, Range<int> range) const {
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

  bool boolean(const json& j, const std::string& path) const {
    if (!j.is_boolean()) fail(path, "must be true or false, got " + type_of(j));
    return j.get<bool>();
  }

  std::string text(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, "must be a string, got " + type_of(j));
    return j.get<std::string>();
  }

  const json& array(const json& j, const std::string& path, size_t size) const {
    if (!j.is_array()) fail(path, "must be an array, got " + type_of(j));
    if (size != 0 && j.size() != size) {
      fail(path, "must have " + std::to_string(size) + " elements, got " + std::to_string(j.size()));
    }
    return j;
  }

  // A vector whose components each lie in the range.
  Vec2 vec2(const json& j, const std::string& path, Range<double> range) const {
    array(j, path, 2);
    return {in_range(j[0], at(path, 0), range), in_range(j[1], at(path, 1), range)};
  }

  const json& required(const json& obj, const std::string& path, const char* key,
                       const std::string& hint = "") const {
    if (!obj.contains(key)) fail(join(path, key), "is missing" + hint);
    return obj.at(key);
  }


  // "bodies[2]" and "angle" make "bodies[2].angle"; "bodies" and 2 make "bodies[2]". `path` is
  // taken by value so that a long path can be moved in and grown in place.
  static std::string join(std::string path, const std::string& key) {
    if (!path.empty()) path += '.';
    path += key;
    return path;
  }
  static std::string at(std::string path, size_t index) {
    path += "[" + std::to_string(index) + "]";
    return path;
  }

  // "a, b, c": keys for messages.
  static std::string list(const std::set<std::string>& keys) {
    std::string out;
    for (const std::string& key : keys) out += (out.empty() ? "" : ", ") + key;
    return out;
  }

 private:
  static std::string type_of(const json& j) {
    return j.is_number() ? "number " + j.dump() : std::string(j.type_name());
  }

  std::string origin_;
};

// nlohmann-json keeps the last of two equal keys in an object, so a file with "angle" twice in a
// body would run with one of them silently dropped. The parser reports each step of its reading
// here (json::parse's callback), and a key its object has already is refused. The objects and
// arrays open at that point are kept in a vector, never on the call stack: a file may nest
// 150 000 arrays (see Reader::count).
class DuplicateKeys {
 public:
  explicit DuplicateKeys(const Reader& reader) : reader_(reader) {}

  void on(json::parse_event_t event, const json& parsed) {
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

 private:
  struct Level {
    bool is_object;
    std::set<std::string> keys;  // an object's keys so far
    std::string key;             // an object's latest key
    size_t elements;             // an array's elements so far
  };

  // A value begins; in an array it is the next element.
  void start_value() {
    if (!levels_.empty() && !levels_.back().is_object) ++levels_.back().elements;
  }

  // The path of the latest key, written as the Reader writes paths: "joints[0].anchor".
  std::string path() const {
    std::string p;
    for (const Level& level : levels_) {
      p = level.is_object ? Reader::join(std::move(p), level.key)
                          : Reader::at(std::move(p), level.elements - 1);
    }
    return p;
  }

  const Reader& reader_;
  std::vector<Level> levels_;  // the open objects and arrays, outermost first
};

// Reads obj[key] into `target` with the Reader method `read` when the key is present.
template <typename T, typename... Extra>
void optional(const Reader& r, const json& obj, const std::string& path, const char* key, T& target,
              T (Reader::*read)(const json&, const std::string&, Extra...) const, Extra... extra) {
  if (obj.contains(key)) target = (r.*read)(obj.at(key), Reader::join(path, key), extra...);
}

// Each shape type with the keys it takes, in the order messages list the types.
const std::vector<std::pair<std::string, std::set<std::string>>> shape_keys = {
    {"box", {"type", "half_extents"}},
    {"circle", {"type", "radius"}},
    {"polygon", {"type", "vertices"}},
    {"capsule", {"type", "radius", "length"}},
};

// A polygon's vertices: 3 to 8 points in the body's frame, a convex polygon counter-clockwise
// (polygon_problem) no smaller than the smallest box.
std::vector<Vec2> read_vertices(const Reader& r, const json& j, const std::string& path) {
  r.array(j, path, 0);
  std::vector<Vec2> vertices;
  for (size_t k = 0; k < j.size() && k <= Convex::max_vertices; ++k) {
    vertices.push_back(r.vec2(j[k], Reader::at(path, k), scene_limits::coordinate));
  }
  if (j.size() > Convex::max_vertices) vertices.resize(j.size());  // polygon_problem names the count
  if (const std::optional<std::string> problem = polygon_problem(vertices)) r.fail(path, *problem);
  const double area = polygon_moments(vertices).area;
  if (area < scene_limits::polygon_area) {
    r.fail(path, "the polygon's area " + shortest_number(area) + " m² is below " +
                     shortest_number(scene_limits::polygon_area) + " m², the smallest box's");
  }
  return vertices;
}

ShapeDescription read_shape(const Reader& r, const json& j, const std::string& path) {
  r.object(j, path);
  const std::string type_path = Reader::join(path, "type");
  const std::string names = "\"box\", \"circle\", \"polygon\" or \"capsule\"";
  const std::string type = r.text(r.required(j, path, "type", " (" + names + ")"), type_path);
  const auto keys = std::find_if(shape_keys.begin(), shape_keys.end(),
                                 [&](const auto& entry) { return entry.first == type; });
  if (keys == shape_keys.end()) r.fail(type_path, "must be " + names + ", got \"" + type + "\"");
  for (const auto& item : j.items()) {
    if (keys->second.count(item.key()) != 0) continue;
    const bool another_shapes = std::any_of(shape_keys.begin(), shape_keys.end(), [&](const auto& e) {
      return e.second.count(item.key()) != 0;
    });
    r.fail(Reader::join(path, item.key()),
           (another_shapes ? "a " + type + " has no " + item.key() : std::string("unknown key")) +
               " (a " + type + "'s keys: " + Reader::list(keys->second) + ")");
  }
  ShapeDescription shape;
  const auto size = [&](const char* key, Range<double> range) {
    return r.in_range(r.required(j, path, key), Reader::join(path, key), range);
  };
  if (type == "box") {
    shape.type = ShapeType::box;
    const std::string hp = Reader::join(path, "half_extents");
    const json& he = r.array(r.required(j, path, "half_extents"), hp, 2);
    shape.half_extents = {r.in_range(he[0], Reader::at(hp, 0), scene_limits::size),
                          r.in_range(he[1], Reader::at(hp, 1), scene_limits::size)};
  } else if (type == "circle") {
    shape.type = ShapeType::circle;
    shape.radius = size("radius", scene_limits::size);
  } else if (type == "polygon") {
    shape.type = ShapeType::polygon;
    shape.vertices = read_vertices(r, r.required(j, path, "vertices"), Reader::join(path, "vertices"));
  } else {
    shape.type = ShapeType::capsule;
    shape.radius = size("radius", scene_limits::size);
    shape.length = size("length", scene_limits::capsule_length);
  }
  return shape;
}

BodyDescription read_body(const Reader& r, const json& j, const std::string& path) {
  r.expect_object(j, path, {"name", "shape", "position", "angle", "static", "density", "friction",
                            "restitution", "velocity", "angular_velocity"});
  BodyDescription body;
  body.name = r.text(r.required(j, path, "name"), Reader::join(path, "name"));
  if (body.name.empty()) r.fail(Reader::join(path, "name"), "must not be empty");
  body.shape = read_shape(r, r.required(j, path, "shape"), Reader::join(path, "shape"));
  optional(r, j, path, "position", body.position, &Reader::vec2, scene_limits::coordinate);
  optional(r, j, path, "angle", body.angle, &Reader::in_range, scene_limits::angle);
  optional(r, j, path, "static", body.is_static, &Reader::boolean);
  optional(r, j, path, "density", body.density, &Reader::in_range, scene_limits::density);
  optional(r, j, path, "friction", body.friction, &Reader::in_range, scene_limits::friction);
  optional(r, j, path, "restitution", body.restitution, &Reader::in_range,
           scene_limits::restitution);
  optional(r, j, path, "velocity", body.velocity, &Reader::vec2, scene_limits::speed);
  optional(r, j, path, "angular_velocity", body.angular_velocity, &Reader::in_range,
           scene_limits::angular_speed);
  return body;
}

// Each joint type with the keys it takes, in the order messages list the types.
const std::vector<std::pair<JointType, std::set<std::string>>> joint_keys = {
    {JointType::revolute, {"type", "bodies", "anchor"}},
    {JointType::distance, {"type", "bodies", "anchors"}},
    {JointType::angle_limit, {"type", "bodies", "lower", "upper"}},
    {JointType::incline, {"type", "body", "point", "normal", "one_sided"}},
};

// "\"revolute\", \"distance\", \"angle_limit\" or \"incline\"", for messages.
std::string joint_type_names() {
  std::string names;
  for (size_t k = 0; k < joint_keys.size(); ++k) {
    names += std::string(k == 0 ? "" : k + 1 == joint_keys.size() ? " or " : ", ") + "\"" +
             joint_type_name(joint_keys[k].first) + "\"";
  }
  return names;
}

// The name of a body of the scene, read from a string at `path`.
std::string body_name(const Reader& r, const json& j, const std::string& path,
                      const std::set<std::string>& bodies) {
  std::string name = r.text(j, path);
  if (bodies.count(name) == 0) r.fail(path, "no body is named \"" + name + "\"");
  return name;
}

// An angle limit's sides: at least one, each within ±π, and lower ≤ upper when both are given.
void read_angle_limit(const Reader& r, const json& j, const std::string& path,
                      JointDescription& joint) {
  for (auto [key, side] : {std::pair{"lower", &joint.lower}, std::pair{"upper", &joint.upper}}) {
    if (j.contains(key)) {
      *side = r.in_range(j.at(key), Reader::join(path, key), scene_limits::angle_limit);
    }
  }
  if (!joint.lower && !joint.upper) r.fail(path, "an angle limit needs \"lower\", \"upper\" or both");
  if (joint.lower && joint.upper && *joint.upper < *joint.lower) {
    r.fail(Reader::join(path, "upper"), "must not be below lower (" + shortest_number(*joint.lower) +
                                            "), got " + shortest_number(*joint.upper));
  }
}

// `bodies` holds every body of the scene by name. A joint's physical rules (two different bodies,
// not both static, a rod of some length, a unit normal) are the engine's: build_world reports
// them with the joint's JSON path.
JointDescription read_joint(const Reader& r, const json& j, const std::string& path,
                            const std::set<std::string>& bodies) {
  r.object(j, path);
  const std::string type_path = Reader::join(path, "type");
  const std::string type =
      r.text(r.required(j, path, "type", " (" + joint_type_names() + ")"), type_path);
  const auto form = std::find_if(joint_keys.begin(), joint_keys.end(),
                                 [&type](const auto& f) { return type == joint_type_name(f.first); });
  if (form == joint_keys.end()) {
    r.fail(type_path, "must be " + joint_type_names() + ", got \"" + type + "\"");
  }
  r.expect_object(j, path, form->second);
  JointDescription joint;
  joint.type = form->first;
  if (joint.type == JointType::incline) {
    joint.body = body_name(r, r.required(j, path, "body"), Reader::join(path, "body"), bodies);
    joint.point = r.vec2(r.required(j, path, "point"), Reader::join(path, "point"),
                         scene_limits::coordinate);
    joint.normal = r.vec2(r.required(j, path, "normal"), Reader::join(path, "normal"),
                          scene_limits::normal_component);
    optional(r, j, path, "one_sided", joint.one_sided, &Reader::boolean);
    return joint;
  }
  const std::string bp = Reader::join(path, "bodies");
  const json& pair = r.array(r.required(j, path, "bodies"), bp, 2);
  for (size_t k = 0; k < 2; ++k) joint.bodies[k] = body_name(r, pair[k], Reader::at(bp, k), bodies);
  if (joint.type == JointType::revolute) {
    joint.anchor = r.vec2(r.required(j, path, "anchor"), Reader::join(path, "anchor"),
                          scene_limits::coordinate);
  } else if (joint.type == JointType::distance) {
    const std::string ap = Reader::join(path, "anchors");
    const json& anchors = r.array(r.required(j, path, "anchors"), ap, 2);
    joint.anchors = {r.vec2(anchors[0], Reader::at(ap, 0), scene_limits::coordinate),
                     r.vec2(anchors[1], Reader::at(ap, 1), scene_limits::coordinate)};
  } else {
    read_angle_limit(r, j, path, joint);
  }
  return joint;
}

Scene read_scene(const Reader& r, const json& j) {
  r.expect_object(j, "", {"name", "description", "solver", "gravity", "dt", "iterations", "beta", "steps",
                          "bodies", "joints"});
  Scene scene;
  optional(r, j, "", "name", scene.name, &Reader::text);
  optional(r, j, "", "description", scene.description, &Reader::text);
  Vec2 gravity = scene.step.gravity.head<2>();
  optional(r, j, "", "gravity", gravity, &Reader::vec2, scene_limits::gravity);
  scene.step.gravity = Vec3(gravity.x(), gravity.y(), 0.0);
  optional(r, j, "", "solver", scene.solver, &Reader::text);
  optional(r, j, "", "dt", scene.step.dt, &Reader::in_range, scene_limits::dt);
  optional(r, j, "", "iterations", scene.step.iterations, &Reader::count, scene_limits::iterations);
  optional(r, j, "", "beta", scene.step.beta, &Reader::in_range, scene_limits::beta);
  optional(r, j, "", "steps", scene.steps, &Reader::count, scene_limits::steps);
  const json& bodies = r.array(r.required(j, "", "bodies"), "bodies", 0);
  std::set<std::string> names;  // every body so far
  for (size_t i = 0; i < bodies.size(); ++i) {
    scene.bodies.push_back(read_body(r, bodies[i], Reader::at("bodies", i)));
    const BodyDescription& body = scene.bodies.back();
    if (!names.insert(body.name).second) {
      r.fail(Reader::at("bodies", i) + ".name", "duplicate body name \"" + body.name + "\"");
    }
  }
  if (j.contains("joints")) {
    const json& joints = r.array(j.at("joints"), "joints", 0);
    for (size_t i = 0; i < joints.size(); ++i) {
      scene.joints.push_back(read_joint(r, joints[i], Reader::at("joints", i), names));
    }
  }
  return scene;
}

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& origin) {
  const Reader reader(origin);
  json document;
  try {
    DuplicateKeys duplicates(reader);
    document = json::parse(json_text, [&duplicates](int, json::parse_event_t event, json& parsed) {
      duplicates.on(event, parsed);
      return true;  // keep every value
    });
  } catch (const json::parse_error& e) {
    throw SceneError(origin + ": not valid JSON: " + e.what());
  } catch (const json::out_of_range& e) {
    throw SceneError(origin + ": a number is not finite as a double: " + e.what());
  }
  return read_scene(reader, document);
}

Scene read_scene_file(const std::string& path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw SceneError(path + ": is a folder, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the scene file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_scene(text, path);
}

std::string scene_to_json(const Scene& scene) { return layout_json(scene_document(scene)) + "\n"; }

}  // namespace lamina
