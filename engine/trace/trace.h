// A trace of a run: what every step left behind, one record per step, for students, graders
// and other tools (docs/lamina-command.md, "Traces").
//
//   bodies    the dynamic bodies after the step (static ones never move and are left out)
//   contacts  the contacts solved in the step, each with its normal n from the first named body
//             to the second and its impulses λ Δt (N·s, comparable with Box2D's; λ is a force)
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/world.h"
#include "scene/scene.h"

namespace lamina {

struct BodyState {
  std::string name;               // the scene's name for the body
  Vec2 position{0.0, 0.0};       // centre of mass x, in m
  double angle = 0.0;             // θ about z, in rad, in (−π, π]
  Vec2 velocity{0.0, 0.0};       // v, in m/s
  double angular_velocity = 0.0;  // ω about z, in rad/s
};

struct ContactState {
  std::array<std::string, 2> bodies;  // the two bodies' names, first then second
  Vec2 point{0.0, 0.0};              // c, midway between the surfaces, in m
  Vec2 normal{0.0, 1.0};             // n, unit, from the first body to the second
  double depth = 0.0;                 // −C of eq. 4-1, in m (negative: apart, kept by the cache)
  double normal_impulse = 0.0;        // λ Δt of the contact row, in N·s
  double tangent_impulse = 0.0;       // λ Δt of the friction row along u1 = z × n, in N·s
  bool cached = false;                // re-placed from the cache (false: this step's deepest point)
  std::string origin = "new";         // "new", "refound" or "kept" (Fig 4-2..4-5): cached ⇔ "kept"
};

struct TraceStep {
  long step = 0;                      // k: step k went from t = k Δt to t + Δt (from 0)
  double time = 0.0;                  // t after the step, in s
  std::vector<BodyState> bodies;      // dynamic bodies, in the scene's order
  std::vector<ContactState> contacts; // in the order the solver took them
};

// The record of the step just taken by a world built from `scene` (build_world: World body i
// is scene.bodies[i]).
TraceStep trace_step(const Scene& scene, const World& world, long step);
// The same, written over `record`: a run that traces every step refills one record, its
// lists and names keeping their memory from step to step.
void trace_step(const Scene& scene, const World& world, long step, TraceStep& record);

}  // namespace lamina
