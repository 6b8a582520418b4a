#include "lamina/world_explanation.h"

namespace lamina::cli {
namespace {

using tutorial::Json;
using tutorial::json_of;
using tutorial::Section;

Section contact_section(const Scene& scene, const ContactInfo& c, double dt) {
  const std::string& a = scene.bodies[c.bodies.first].name;
  const std::string& b = scene.bodies[c.bodies.second].name;
  return {"contact " + a + " – " + b + (c.cached ? " (cached, Fig 4-4)" : " (this step's deepest point, Fig 4-2)"),
          {{"c", "", "contact point, midway between the surfaces", json_of(c.point), "m"},
           {"n", "4-1", "normal, from " + a + " to " + b, json_of(c.normal), ""},
           {"C", "4-1", "separation (negative: penetrating)", Json(c.separation), "m"},
           {"λ", "3-16", "contact force the solver found", Json(c.lambda_normal), "N"},
           {"λ Δt", "", "normal impulse over the step", Json(c.lambda_normal * dt), "N·s"},
           {"λt", "", "friction force along u1 = z × n", Json(c.lambda_tangent), "N"}}};
}

Section body_section(const std::string& name, const RigidBody& body) {
  return {name,
          {{"x(t+Δt)", "2-5", "centre of mass", json_of(body.x), "m"},
           {"θ(t+Δt)", "2-6", "angle about z", Json(planar_angle(body.q)), "rad"},
           {"v(t+Δt)", "2-3", "velocity", json_of(body.v), "m/s"},
           {"ω(t+Δt)", "2-4", "angular velocity", json_of(body.angular_velocity), "rad/s"}}};
}

}  // namespace

tutorial::Explanation world_explanation(const Scene& scene, const World& world,
                                        const WorldReport& report) {
  tutorial::Explanation explanation;
  for (const ContactInfo& c : report.contacts) {
    explanation.push_back(contact_section(scene, c, world.settings().dt));
  }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (!scene.bodies[i].is_static) explanation.push_back(body_section(scene.bodies[i].name, world.bodies()[i]));
  }
  return explanation;
}

}  // namespace lamina::cli
