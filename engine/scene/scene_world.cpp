#include "scene/scene_world.h"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "constraints/angle_limit.h"
#include "constraints/distance_constraint.h"
#include "constraints/incline_constraint.h"
#include "constraints/revolute_joint.h"
#include "beyond/methods.h"
#include "kinematics/mass_properties.h"

namespace lamina {
namespace {

Vec3 planar(const Vec2& v) { return Vec3(v.x(), v.y(), 0.0); }

// A polygon's or a capsule's area moments about its centre of mass.
AreaMoments moments_of(const Shape& shape) {
  if (shape.kind == Shape::Kind::capsule) return capsule_moments(shape.radius, shape.length);
  return polygon_moments(
      std::vector<Vec2>(shape.vertices.begin(), shape.vertices.begin() + shape.vertex_count));
}

int add_body(World& world, const BodyDescription& desc) {
  const Material material{desc.friction, desc.restitution};
  const ShapeDescription& s = desc.shape;
  const PlacedShape placed = place_shape(desc);
  const Vec3 x = planar(placed.centre);
  if (desc.is_static) {
    return world.add_body(RigidBody::static_body(x, planar_orientation(desc.angle)), placed.shape,
                          material);
  }
  RigidBody body =
      s.type == ShapeType::box
          ? box_body(desc.density, s.half_extents[0], s.half_extents[1], x, desc.angle)
      : s.type == ShapeType::circle
          ? disc_body(desc.density, s.radius, x, desc.angle)
          : prism_body(desc.density, moments_of(placed.shape), x, desc.angle);
  body.v = planar(desc.velocity);
  body.angular_velocity = Vec3(0.0, 0.0, desc.angular_velocity);
  return world.add_body(body, placed.shape, material);
}

// The engine constraints of a scene's joint: one, or for an angle limit with both sides two, as
// AngleLimit is one-sided (the lower side's row first). `index_of` gives each body's index.
std::vector<std::unique_ptr<Constraint>> make_joint(const World& world,
                                                    const JointDescription& desc,
                                                    const std::map<std::string, int>& index_of) {
  const std::vector<RigidBody>& bodies = world.bodies();
  std::vector<std::unique_ptr<Constraint>> made;
  if (desc.type == JointType::incline) {
    const InclineKind kind = desc.one_sided ? InclineKind::one_sided : InclineKind::bilateral;
    made.push_back(std::make_unique<InclineConstraint>(index_of.at(desc.body), planar(desc.point),
                                                       planar(desc.normal), kind));
    return made;
  }
  const int a = index_of.at(desc.bodies[0]);
  const int b = index_of.at(desc.bodies[1]);
  if (desc.type == JointType::revolute) {
    const Vec3 pin = planar(desc.anchor);
    made.push_back(
        std::make_unique<RevoluteJoint>(anchor_at(bodies, a, pin), anchor_at(bodies, b, pin)));
  } else if (desc.type == JointType::distance) {
    const Vec3 end_a = planar(desc.anchors[0]);
    const Vec3 end_b = planar(desc.anchors[1]);
    made.push_back(std::make_unique<DistanceConstraint>(
        anchor_at(bodies, a, end_a), anchor_at(bodies, b, end_b), (end_b - end_a).norm()));
  } else {
    if (desc.lower) made.push_back(std::make_unique<AngleLimit>(a, b, *desc.lower, LimitSide::lower));
    if (desc.upper) made.push_back(std::make_unique<AngleLimit>(a, b, *desc.upper, LimitSide::upper));
  }
  return made;
}

// `("ground", "bar")`: the bodies of a joint, named after its JSON path in messages.
std::string joint_bodies(const JointDescription& joint) {
  if (joint.type == JointType::incline) return "(\"" + joint.body + "\")";
  return "(\"" + joint.bodies[0] + "\", \"" + joint.bodies[1] + "\")";
}

// Runs `add`; an engine refusal is rethrown with the JSON path of the scene's value in front.
template <class Add>
auto at_path(const std::string& path, Add&& add) {
  try {
    return add();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

}  // namespace

PlacedShape place_shape(const BodyDescription& body) {
  const ShapeDescription& s = body.shape;
  PlacedShape placed{Shape::box(s.half_extents[0], s.half_extents[1]), body.position};
  if (s.type == ShapeType::circle) {
    placed.shape = Shape::circle(s.radius);
  } else if (s.type == ShapeType::capsule) {
    placed.shape = Shape::capsule(s.radius, s.length);
  } else if (s.type == ShapeType::polygon) {
    const Vec2 c = polygon_moments(s.vertices).centroid;
    std::vector<Vec2> about_centroid;
    for (const Vec2& v : s.vertices) about_centroid.push_back(v - c);
    placed.shape = Shape::polygon(about_centroid);
    placed.centre += planar_orientation(body.angle).toRotationMatrix().topLeftCorner<2, 2>() * c;
  }
  return placed;
}

WorldSettings world_settings(const Scene& scene) {
  WorldSettings settings;
  settings.step = scene.step;
  return with_method(settings, scene.solver);
}

World build_world(const Scene& scene, const WorldSettings& settings) {
  World world(settings);
  std::map<std::string, int> index_of;
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    const BodyDescription& desc = scene.bodies[i];
    index_of[desc.name] = at_path("bodies[" + std::to_string(i) + "]", [&] { return add_body(world, desc); });
  }
  for (size_t i = 0; i < scene.joints.size(); ++i) {
    const JointDescription& joint = scene.joints[i];
    at_path("joints[" + std::to_string(i) + "] " + joint_bodies(joint), [&] {
      for (std::unique_ptr<Constraint>& made : make_joint(world, joint, index_of)) {
        world.add_joint(std::move(made));
      }
    });
  }
  return world;
}

}  // namespace lamina
