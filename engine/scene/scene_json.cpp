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
#include "language/language.h"
#include "scene/json_layout.h"
#include "scene/json_reader.h"
#include "scene/scene_limits.h"
#include "scene/shortest_number.h"

namespace lamina {
namespace {

using nlohmann::json;
using scene_limits::Range;

// Reads obj[key] into `target` with the JsonReader method `read` when the key is present.
template <typename T, typename... Extra>
void optional(const JsonReader& r, const json& obj, const std::string& path, const char* key, T& target,
              T (JsonReader::*read)(const json&, const std::string&, Extra...) const, Extra... extra) {
  if (obj.contains(key)) target = (r.*read)(obj.at(key), JsonReader::join(path, key), extra...);
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
std::vector<Vec2> read_vertices(const JsonReader& r, const json& j, const std::string& path) {
  r.array(j, path, 0);
  std::vector<Vec2> vertices;
  for (size_t k = 0; k < j.size() && k <= Convex::max_vertices; ++k) {
    vertices.push_back(r.vec2(j[k], JsonReader::at(path, k), scene_limits::coordinate));
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

ShapeDescription read_shape(const JsonReader& r, const json& j, const std::string& path) {
  r.object(j, path);
  const std::string type_path = JsonReader::join(path, "type");
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
    r.fail(JsonReader::join(path, item.key()),
           (another_shapes ? "a " + type + " has no " + item.key() : std::string("unknown key")) +
               " (a " + type + "'s keys: " + JsonReader::list(keys->second) + ")");
  }
  ShapeDescription shape;
  const auto size = [&](const char* key, Range<double> range) {
    return r.in_range(r.required(j, path, key), JsonReader::join(path, key), range);
  };
  if (type == "box") {
    shape.type = ShapeType::box;
    const std::string hp = JsonReader::join(path, "half_extents");
    const json& he = r.array(r.required(j, path, "half_extents"), hp, 2);
    shape.half_extents = {r.in_range(he[0], JsonReader::at(hp, 0), scene_limits::size),
                          r.in_range(he[1], JsonReader::at(hp, 1), scene_limits::size)};
  } else if (type == "circle") {
    shape.type = ShapeType::circle;
    shape.radius = size("radius", scene_limits::size);
  } else if (type == "polygon") {
    shape.type = ShapeType::polygon;
    shape.vertices = read_vertices(r, r.required(j, path, "vertices"), JsonReader::join(path, "vertices"));
  } else {
    shape.type = ShapeType::capsule;
    shape.radius = size("radius", scene_limits::size);
    shape.length = size("length", scene_limits::capsule_length);
  }
  return shape;
}

BodyDescription read_body(const JsonReader& r, const json& j, const std::string& path) {
  r.expect_object(j, path, {"name", "shape", "position", "angle", "static", "density", "friction",
                            "restitution", "velocity", "angular_velocity"});
  BodyDescription body;
  body.name = r.text(r.required(j, path, "name"), JsonReader::join(path, "name"));
  if (body.name.empty()) r.fail(JsonReader::join(path, "name"), "must not be empty");
  body.shape = read_shape(r, r.required(j, path, "shape"), JsonReader::join(path, "shape"));
  optional(r, j, path, "position", body.position, &JsonReader::vec2, scene_limits::coordinate);
  optional(r, j, path, "angle", body.angle, &JsonReader::in_range, scene_limits::angle);
  optional(r, j, path, "static", body.is_static, &JsonReader::boolean);
  optional(r, j, path, "density", body.density, &JsonReader::in_range, scene_limits::density);
  optional(r, j, path, "friction", body.friction, &JsonReader::in_range, scene_limits::friction);
  optional(r, j, path, "restitution", body.restitution, &JsonReader::in_range,
           scene_limits::restitution);
  optional(r, j, path, "velocity", body.velocity, &JsonReader::vec2, scene_limits::speed);
  optional(r, j, path, "angular_velocity", body.angular_velocity, &JsonReader::in_range,
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
std::string body_name(const JsonReader& r, const json& j, const std::string& path,
                      const std::set<std::string>& bodies) {
  std::string name = r.text(j, path);
  if (bodies.count(name) == 0) r.fail(path, "no body is named \"" + name + "\"");
  return name;
}

// An angle limit's sides: at least one, each within ±π, and lower ≤ upper when both are given.
void read_angle_limit(const JsonReader& r, const json& j, const std::string& path,
                      JointDescription& joint) {
  for (auto [key, side] : {std::pair{"lower", &joint.lower}, std::pair{"upper", &joint.upper}}) {
    if (j.contains(key)) {
      *side = r.in_range(j.at(key), JsonReader::join(path, key), scene_limits::angle_limit);
    }
  }
  if (!joint.lower && !joint.upper) r.fail(path, "an angle limit needs \"lower\", \"upper\" or both");
  if (joint.lower && joint.upper && *joint.upper < *joint.lower) {
    r.fail(JsonReader::join(path, "upper"), "must not be below lower (" + shortest_number(*joint.lower) +
                                            "), got " + shortest_number(*joint.upper));
  }
}

// `bodies` holds every body of the scene by name. A joint's physical rules (two different bodies,
// not both static, a rod of some length, a unit normal) are the engine's: build_world reports
// them with the joint's JSON path.
JointDescription read_joint(const JsonReader& r, const json& j, const std::string& path,
                            const std::set<std::string>& bodies) {
  r.object(j, path);
  const std::string type_path = JsonReader::join(path, "type");
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
    joint.body = body_name(r, r.required(j, path, "body"), JsonReader::join(path, "body"), bodies);
    joint.point = r.vec2(r.required(j, path, "point"), JsonReader::join(path, "point"),
                         scene_limits::coordinate);
    joint.normal = r.vec2(r.required(j, path, "normal"), JsonReader::join(path, "normal"),
                          scene_limits::normal_component);
    optional(r, j, path, "one_sided", joint.one_sided, &JsonReader::boolean);
    return joint;
  }
  const std::string bp = JsonReader::join(path, "bodies");
  const json& pair = r.array(r.required(j, path, "bodies"), bp, 2);
  for (size_t k = 0; k < 2; ++k) joint.bodies[k] = body_name(r, pair[k], JsonReader::at(bp, k), bodies);
  if (joint.type == JointType::revolute) {
    joint.anchor = r.vec2(r.required(j, path, "anchor"), JsonReader::join(path, "anchor"),
                          scene_limits::coordinate);
  } else if (joint.type == JointType::distance) {
    const std::string ap = JsonReader::join(path, "anchors");
    const json& anchors = r.array(r.required(j, path, "anchors"), ap, 2);
    joint.anchors = {r.vec2(anchors[0], JsonReader::at(ap, 0), scene_limits::coordinate),
                     r.vec2(anchors[1], JsonReader::at(ap, 1), scene_limits::coordinate)};
  } else {
    read_angle_limit(r, j, path, joint);
  }
  return joint;
}

Scene read_scene(const JsonReader& r, const json& j) {
  r.expect_object(j, "", {"name", "description", "solver", "gravity", "dt", "iterations", "beta", "steps",
                          "lang", "bodies", "joints"});
  Scene scene;
  optional(r, j, "", "name", scene.name, &JsonReader::text);
  optional(r, j, "", "description", scene.description, &JsonReader::text);
  Vec2 gravity = scene.step.gravity.head<2>();
  optional(r, j, "", "gravity", gravity, &JsonReader::vec2, scene_limits::gravity);
  scene.step.gravity = Vec3(gravity.x(), gravity.y(), 0.0);
  optional(r, j, "", "solver", scene.solver, &JsonReader::text);
  optional(r, j, "", "dt", scene.step.dt, &JsonReader::in_range, scene_limits::dt);
  optional(r, j, "", "iterations", scene.step.iterations, &JsonReader::count, scene_limits::iterations);
  optional(r, j, "", "beta", scene.step.beta, &JsonReader::in_range, scene_limits::beta);
  optional(r, j, "", "steps", scene.steps, &JsonReader::count, scene_limits::steps);
  optional(r, j, "", "lang", scene.lang, &JsonReader::text);
  if (j.contains("lang") && !language_named(scene.lang)) {
    r.fail("lang", "must be one of " + language_codes() + ", got \"" + scene.lang + "\"");
  }
  const json& bodies = r.array(r.required(j, "", "bodies"), "bodies", 0);
  std::set<std::string> names;  // every body so far
  for (size_t i = 0; i < bodies.size(); ++i) {
    scene.bodies.push_back(read_body(r, bodies[i], JsonReader::at("bodies", i)));
    const BodyDescription& body = scene.bodies.back();
    if (!names.insert(body.name).second) {
      r.fail(JsonReader::at("bodies", i) + ".name", "duplicate body name \"" + body.name + "\"");
    }
  }
  if (j.contains("joints")) {
    const json& joints = r.array(j.at("joints"), "joints", 0);
    for (size_t i = 0; i < joints.size(); ++i) {
      scene.joints.push_back(read_joint(r, joints[i], JsonReader::at("joints", i), names));
    }
  }
  return scene;
}

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& origin) {
  const JsonReader reader(origin);
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
