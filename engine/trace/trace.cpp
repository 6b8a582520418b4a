#include "trace/trace.h"

#include <cassert>

namespace lamina {
namespace {

Vec2 plane(const Vec3& v) { return {v.x(), v.y()}; }

BodyState body_state(const std::string& name, const RigidBody& body) {
  return {name, plane(body.x), planar_angle(body.q), plane(body.v), body.angular_velocity.z()};
}

// x with −0 written as 0 (a resting contact's C and λ are often −0, which reads as a sign).
double unsigned_zero(double x) { return x + 0.0; }

ContactState contact_state(const Scene& scene, const ContactInfo& c, double dt) {
  return {{scene.bodies[c.bodies.first].name, scene.bodies[c.bodies.second].name},
          plane(c.point),
          plane(c.normal),
          unsigned_zero(-c.separation),
          unsigned_zero(c.lambda_normal * dt),  // λ is a force; the impulse over the step is λ Δt
          unsigned_zero(c.lambda_tangent * dt),
          c.cached,
          origin_name(c.origin)};
}

}  // namespace

TraceStep trace_step(const Scene& scene, const World& world, long step) {
  const std::vector<RigidBody>& bodies = world.bodies();
  assert(bodies.size() == scene.bodies.size());
  TraceStep record{step, world.time(), {}, {}};
  // room for every record at once: grown one by one, a pyramid's ~800 contacts were moved
  // about ten times a step (a quarter of this function's instructions, callgrind)
  record.bodies.reserve(bodies.size());
  record.contacts.reserve(world.contacts().size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!scene.bodies[i].is_static) record.bodies.push_back(body_state(scene.bodies[i].name, bodies[i]));
  }
  for (const ContactInfo& c : world.contacts()) {
    record.contacts.push_back(contact_state(scene, c, world.settings().step.dt));
  }
  return record;
}

}  // namespace lamina
