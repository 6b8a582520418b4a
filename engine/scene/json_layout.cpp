#include "scene/json_layout.h"

namespace lamina {
namespace {

using Json = nlohmann::ordered_json;

Json vec2_json(const Vec2& v) { return Json::array({v[0], v[1]}); }

Json shape_json(const ShapeDescription& shape) {
  switch (shape.type) {
    case ShapeType::circle:
      return {{"type", "circle"}, {"radius", shape.radius}};
    case ShapeType::polygon: {
      Json vertices = Json::array();
      for (const Vec2& v : shape.vertices) vertices.push_back(vec2_json(v));
      return {{"type", "polygon"}, {"vertices", vertices}};
    }
    case ShapeType::capsule:
      return {{"type", "capsule"}, {"radius", shape.radius}, {"length", shape.length}};
    case ShapeType::box:
      break;
  }
  return {{"type", "box"}, {"half_extents", vec2_json(shape.half_extents)}};
}

Json body_json(const BodyDescription& b) {
  Json j = {{"name", b.name}, {"shape", shape_json(b.shape)}, {"position", vec2_json(b.position)},
            {"angle", b.angle}, {"static", b.is_static}, {"friction", b.friction},
            {"restitution", b.restitution}};
  if (!b.is_static) {
    j["density"] = b.density;
    j["velocity"] = vec2_json(b.velocity);
    j["angular_velocity"] = b.angular_velocity;
  }
  return j;
}

// An angle limit writes only the sides it has: a side not given is not limited.
Json joint_json(const JointDescription& joint) {
  Json j = {{"type", joint_type_name(joint.type)}};
  if (joint.type == JointType::incline) {
    j["body"] = joint.body;
    j["point"] = vec2_json(joint.point);
    j["normal"] = vec2_json(joint.normal);
    j["one_sided"] = joint.one_sided;
    return j;
  }
  j["bodies"] = {joint.bodies[0], joint.bodies[1]};
  if (joint.type == JointType::revolute) {
    j["anchor"] = vec2_json(joint.anchor);
  } else if (joint.type == JointType::distance) {
    j["anchors"] = {vec2_json(joint.anchors[0]), vec2_json(joint.anchors[1])};
  } else {
    if (joint.lower) j["lower"] = *joint.lower;
    if (joint.upper) j["upper"] = *joint.upper;
  }
  return j;
}

std::string key_prefix(const std::string& key) { return key.empty() ? "" : Json(key).dump() + ": "; }

// The value on one line, with a space after each ',' and ':'.
std::string one_line(const Json& value) {
  if (!value.is_structured()) return value.dump();
  std::string text;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!text.empty()) text += ", ";
    text += (value.is_object() ? key_prefix(it.key()) : "") + one_line(it.value());
  }
  return value.is_object() ? "{" + text + "}" : "[" + text + "]";
}

// `key: value` (no key inside arrays) at `indent` spaces, on one line when it fits.
std::string laid_out(const std::string& key, const Json& value, std::size_t indent, std::size_t width) {
  const std::string margin(indent, ' ');
  const std::string flat = margin + key_prefix(key) + one_line(value);
  if (!value.is_structured() || value.empty() || flat.size() <= width) return flat;
  std::string text = margin + key_prefix(key) + (value.is_object() ? "{" : "[");
  for (auto it = value.begin(); it != value.end(); ++it) {
    text += (it == value.begin() ? "\n" : ",\n") +
            laid_out(value.is_object() ? it.key() : "", it.value(), indent + 2, width);
  }
  return text + "\n" + margin + (value.is_object() ? "}" : "]");
}

}  // namespace

const char* joint_type_name(JointType type) {
  switch (type) {
    case JointType::revolute: return "revolute";
    case JointType::distance: return "distance";
    case JointType::angle_limit: return "angle_limit";
    case JointType::incline: return "incline";
  }
  return "";
}

Json scene_document(const Scene& scene) {
  Json j = {{"name", scene.name}, {"description", scene.description}, {"solver", scene.solver},
            {"gravity", vec2_json(scene.step.gravity.head<2>())}, {"dt", scene.step.dt},
            {"iterations", scene.step.iterations}, {"beta", scene.step.beta},
            {"steps", scene.steps}, {"bodies", Json::array()}, {"joints", Json::array()}};
  if (!scene.lang.empty()) j["lang"] = scene.lang;  // only a file that says so
  for (const BodyDescription& body : scene.bodies) j["bodies"].push_back(body_json(body));
  for (const JointDescription& joint : scene.joints) j["joints"].push_back(joint_json(joint));
  return j;
}

std::string layout_json(const Json& value, std::size_t width) { return laid_out("", value, 0, width); }

}  // namespace lamina
