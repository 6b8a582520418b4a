#include "app/reference/box2d_lab.h"

#include <algorithm>
#include <cmath>

#include "app/reference/box2d_scene.h"
#include "scene/builtin_scenes.h"

namespace lamina {
namespace {

std::vector<Pose> poses_of(const Box2dScene& b2) {
  std::vector<Pose> poses;
  for (const b2Body* body : b2.bodies) {
    poses.emplace_back(body->GetPosition().x, body->GetPosition().y, body->GetAngle());
  }
  return poses;
}

// The skin Box2D keeps around a shape: b2_polygonRadius for a polygon, none for a circle.
double skin(const b2Fixture* fixture) {
  return fixture->GetType() == b2Shape::e_polygon ? fixture->GetShape()->m_radius : 0.0;
}

// The deepest overlap of the shapes themselves over every touching contact, in m.
double deepest_overlap(b2World& world) {
  double deepest = 0.0;
  for (b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext()) {
    if (!c->IsTouching()) continue;
    b2WorldManifold manifold;
    c->GetWorldManifold(&manifold);
    const double skins = skin(c->GetFixtureA()) + skin(c->GetFixtureB());
    for (int k = 0; k < c->GetManifold()->pointCount; ++k) {
      deepest = std::max(deepest, -(manifold.separations[k] + skins));
    }
  }
  return deepest;
}

// Σ ½ m v² + ½ I ω² − m g·x over the moving bodies, in J (each body's origin is its centre).
double energy(const Box2dScene& b2) {
  const b2Vec2 g = b2.world->GetGravity();
  double e = 0.0;
  for (const b2Body* body : b2.bodies) {
    if (body->GetType() != b2_dynamicBody) continue;
    const b2Vec2 v = body->GetLinearVelocity();
    const double m = body->GetMass(), w = body->GetAngularVelocity();
    e += 0.5 * m * (v.x * v.x + v.y * v.y) + 0.5 * body->GetInertia() * w * w -
         m * (g.x * body->GetPosition().x + g.y * body->GetPosition().y);
  }
  return e;
}

}  // namespace

LabRun run_box2d_lab(const std::string& scene_name, int steps) {
  const Scene scene = builtin_scene(scene_name);
  Box2dScene b2 = make_box2d_scene(scene);
  LabMeter meter(scene, box2d_name, poses_of(b2));
  const double start = thread_cpu_seconds();
  for (int k = 0; k < steps; ++k) {
    b2.step();
    const std::vector<Pose> poses = poses_of(b2);
    if (std::any_of(poses.begin(), poses.end(), [](const Pose& p) { return !p.allFinite(); })) {
      meter.diverged();
      break;
    }
    meter.sample((k + 1) * scene.step.dt, poses, deepest_overlap(*b2.world), energy(b2));
  }
  meter.cost(thread_cpu_seconds() - start);
  return meter.run();
}

}  // namespace lamina
