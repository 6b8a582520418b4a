#include "trace/trace.h"

#include <cassert>
#include <string_view>

namespace lamina {
namespace {

Vec2 plane(const Vec3& v) { return {v.x(), v.y()}; }

// `to` made equal to `from`: most names are the same as in the step before (a record is
// refilled each step), and comparing is cheaper than copying.
void set_text(std::string& to, const std::string& from) {
  if (to != from) to = from;
}

void fill_body_state(BodyState& state, const std::string& name, const RigidBody& body) {
  set_text(state.name, name);
  state.position = plane(body.x);
  state.angle = planar_angle(body.q);
  state.velocity = plane(body.v);
  state.angular_velocity = body.angular_velocity.z();
}

// x with −0 written as 0 (a resting contact's C and λ are often −0, which reads as a sign).
double unsigned_zero(double x) { return x + 0.0; }

void fill_contact_state(ContactState& state, const Scene& scene, const ContactInfo& c, double dt) {
  set_text(state.bodies[0], scene.bodies[c.bodies.first].name);
  set_text(state.bodies[1], scene.bodies[c.bodies.second].name);
  state.point = plane(c.point);
  state.normal = plane(c.normal);
  state.depth = unsigned_zero(-c.separation);
  // λ is a force; the impulse over the step is λ Δt
  state.normal_impulse = unsigned_zero(c.lambda_normal * dt);
  state.tangent_impulse = unsigned_zero(c.lambda_tangent * dt);
  state.cached = c.cached;
  const std::string_view origin = origin_name(c.origin);
  if (state.origin != origin) state.origin = origin;  // most contacts keep theirs from step to step
}

}  // namespace

TraceStep trace_step(const Scene& scene, const World& world, long step) {
  TraceStep record;
  trace_step(scene, world, step, record);
  return record;
}

void trace_step(const Scene& scene, const World& world, long step, TraceStep& record) {
  const std::vector<RigidBody>& bodies = world.bodies();
  assert(bodies.size() == scene.bodies.size());
  record.step = step;
  record.time = world.time();
  // Resized, not cleared and grown: the states already there keep their names' memory.
  std::size_t dynamic = 0;
  for (const BodyDescription& body : scene.bodies) dynamic += body.is_static ? 0 : 1;
  record.bodies.resize(dynamic);
  std::size_t k = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!scene.bodies[i].is_static) fill_body_state(record.bodies[k++], scene.bodies[i].name, bodies[i]);
  }
  // Read from the contact pairs in place (World::contacts() would make a list of them first).
  const std::vector<ContactPair>& pairs = world.contact_pairs();
  record.contacts.resize(contact_count(pairs));
  const double dt = world.settings().step.dt;
  std::size_t i = 0;
  for (const ContactPair& pair : pairs) {
    for (int k = 0; k < pair.count; ++k) {
      fill_contact_state(record.contacts[i++], scene, contact_info(pair, k), dt);
    }
  }
}

}  // namespace lamina
