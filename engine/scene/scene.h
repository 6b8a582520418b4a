// A scene as plain data: what a scene file holds, before any engine object is made.
//
// Scene files (JSON) are read into this and written from it (scene_json.h); the built-in scenes
// (builtin_scenes.h) are values of it. All quantities are SI, angles in radians, and every scene
// lies in the x–y plane with y up.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "constraints/step_settings.h"
#include "contact/shape.h"
#include "kinematics/math_types.h"

namespace lamina {

enum class ShapeType { box, circle, polygon, capsule };

struct ShapeDescription {
  ShapeType type = ShapeType::box;
  Vec2 half_extents{0.5, 0.5};  // a box's half width and half height, in m
  double radius = 0.5;           // a circle's or a capsule's radius, in m
  double length = 1.0;           // a capsule's length between its caps' centres, along x, in m
  std::vector<Vec2> vertices;    // a polygon's vertices, counter-clockwise, in the body's frame:
                                 // about its position, not its centroid (BodyDescription)
};

struct BodyDescription {
  std::string name;                  // unique within the scene; joints refer to it
  ShapeDescription shape;
  Vec2 position{0.0, 0.0};          // the origin of the body's frame, in m: the centre of mass,
                                     // except for a polygon, whose centre of mass is its
                                     // vertices' centroid (position + R(angle) c)
  double angle = 0.0;                // about z, in rad
  bool is_static = false;            // a static body never moves (zero inverse mass, eq. 5-1)
  double density = 1.0;              // kg/m² over the shape's area (1 m deep), dynamic bodies only
  double friction = Material().friction;        // μ; two bodies combine as √(μ1 μ2)
  double restitution = Material().restitution;  // e in [0, 1]; two bodies combine as the max
  Vec2 velocity{0.0, 0.0};          // v of the centre of mass, in m/s
  double angular_velocity = 0.0;     // ω about z, in rad/s
};

// The four constraints of chapter 3: a pin, a rod, a joint-angle limit and an incline.
enum class JointType { revolute, distance, angle_limit, incline };

struct JointDescription {
  JointType type = JointType::revolute;
  std::array<std::string, 2> bodies;  // revolute, distance, angle limit: the two bodies' names
  Vec2 anchor{0.0, 0.0};             // revolute: the pin, world frame, in m
  std::array<Vec2, 2> anchors{};     // distance: the rod's end on each body, world frame, in m
  std::optional<double> lower;       // angle limit: θ ≥ lower, θ the second body's angle relative
                                     // to the first in (−π, π], in rad; none: no lower limit
  std::optional<double> upper;       // angle limit: θ ≤ upper, in rad; none: no upper limit
  std::string body;                  // incline: the name of the body whose centre is held
  Vec2 point{0.0, 0.0};              // incline: p, a point of the line, world frame, in m
  Vec2 normal{0.0, 1.0};             // incline: N, the line's unit normal, world frame
  bool one_sided = false;            // incline: (x − p)·N ≥ 0 (Fig 3-2), not = 0 (Fig 3-1)
};

struct Scene {
  std::string name = "scene";
  std::string description;           // one line, shown by `lamina scenes`
  std::string solver = "islands";    // the method the World steps with (beyond/methods.h)
  StepSettings step;                 // g (in the plane), Δt, β and the PGS sweeps per step
  int steps = 600;                   // how many steps `lamina run` takes unless told
  std::string lang;                  // "en" or "ko": the frames' language unless --lang says;
                                     // empty when the file does not say
  std::vector<BodyDescription> bodies;
  std::vector<JointDescription> joints;
};

}  // namespace lamina
