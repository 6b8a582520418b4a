#include "app/reference/box2d_scene.h"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace lamina {
namespace {

b2Vec2 to_b2(const Vec2& v) { return b2Vec2(static_cast<float>(v[0]), static_cast<float>(v[1])); }

b2Body* add_body(b2World& world, const BodyDescription& desc) {
  b2BodyDef def;
  def.type = desc.is_static ? b2_staticBody : b2_dynamicBody;
  def.position = to_b2(desc.position);
  def.angle = static_cast<float>(desc.angle);
  def.linearVelocity = to_b2(desc.velocity);
  def.angularVelocity = static_cast<float>(desc.angular_velocity);
  b2Body* body = world.CreateBody(&def);

  b2PolygonShape polygon;
  b2CircleShape circle;
  b2FixtureDef fixture;
  fixture.shape = &polygon;
  switch (desc.shape.type) {
    case ShapeType::box:
      polygon.SetAsBox(static_cast<float>(desc.shape.half_extents[0]),
                       static_cast<float>(desc.shape.half_extents[1]));
      break;
    case ShapeType::circle:
      circle.m_radius = static_cast<float>(desc.shape.radius);
      fixture.shape = &circle;
      break;
    case ShapeType::polygon: {
      // Box2D's body origin is the vertices' origin, as a Lamina scene's position is; Box2D
      // finds the centroid itself.
      std::vector<b2Vec2> points;
      for (const Vec2& v : desc.shape.vertices) points.push_back(to_b2(v));
      polygon.Set(points.data(), static_cast<int32>(points.size()));
      break;
    }
    case ShapeType::capsule:
      throw std::invalid_argument("body \"" + desc.name + "\": Box2D 2.4.1 has no capsule shape");
  }
  fixture.density = desc.is_static ? 0.0f : static_cast<float>(desc.density);
  fixture.friction = static_cast<float>(desc.friction);
  fixture.restitution = static_cast<float>(desc.restitution);
  body->CreateFixture(&fixture);
  return body;
}

void add_joint(b2World& world, const JointDescription& desc, b2Body* a, b2Body* b) {
  if (desc.type == JointType::revolute) {
    b2RevoluteJointDef def;
    def.Initialize(a, b, to_b2(desc.anchor));
    world.CreateJoint(&def);
    return;
  }
  b2DistanceJointDef def;
  def.Initialize(a, b, to_b2(desc.anchors[0]), to_b2(desc.anchors[1]));
  world.CreateJoint(&def);
}

}  // namespace

Box2dScene make_box2d_scene(const Scene& scene, const Box2dSettings& settings) {
  Box2dScene out;
  out.settings = settings;
  out.dt = static_cast<float>(scene.step.dt);
  out.world = std::make_unique<b2World>(to_b2(scene.step.gravity.head<2>()));
  out.world->SetContinuousPhysics(false);
  out.world->SetAllowSleeping(settings.allow_sleeping);
  std::map<std::string, b2Body*> by_name;
  for (const BodyDescription& desc : scene.bodies) {
    out.bodies.push_back(add_body(*out.world, desc));
    by_name[desc.name] = out.bodies.back();
  }
  for (const JointDescription& joint : scene.joints) {
    add_joint(*out.world, joint, by_name.at(joint.bodies[0]), by_name.at(joint.bodies[1]));
  }
  return out;
}

}  // namespace lamina
