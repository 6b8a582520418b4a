// Scenes built by build_world and watched step by step, for the tests of extreme but valid input
// (issue 9) and of refused input: after every step every body must be finite and exactly in the
// x–y plane. Scenes lie in the x–y plane, y up; the ground is a static box whose top is y = 0.
#pragma once

#include <string>

#include "contact/world.h"
#include "scene/scene.h"

namespace lamina {

inline const double slop = ContactSettings().slop;  // penetration the contacts leave alone, in m

// A scene's World, every body inspected after every step; the first fault stops the run.
struct Watch {
  explicit Watch(const Scene& s, const WorldSettings& settings);
  explicit Watch(const Scene& s);

  // Steps for `seconds` of simulated time (whole steps); false at the first fault.
  bool run_for(double seconds);
  // Looks at every body after a step: records the first fault, the top speed and peak energy.
  void inspect();
  // The World's body that the scene names `name`; throws std::invalid_argument for none.
  const RigidBody& body(const std::string& name) const;

  Scene scene;
  World world;
  long steps_taken = 0;
  std::string fault;         // the first fault, "" while there is none
  double start_energy;       // E at t = 0, in J
  double peak_energy;        // the largest E after any step, in J
  double top_speed = 0.0;    // the largest |v| of a moving body after any step, in m/s
};

// Runs a watched scene and requires every step sound, naming the first fault.
void require_sound(Watch& watch, double seconds);

// A dynamic box (unit half extents unless given) and a dynamic disc, named, at a position.
BodyDescription box(const std::string& name, Vec2 position, Vec2 half_extents = {0.5, 0.5});
BodyDescription circle(const std::string& name, Vec2 position, double radius);

// The ground, a static box 40 m × 1 m whose top is y = 0.
BodyDescription ground();

// The ground and `count` unit boxes placed touching, one on another: "box0" at the bottom.
Scene stack(int count, double dt = 1.0 / 60.0, int iterations = 10);

// The energy of lifting every moving body by the slop, Σ m g slop, in J: what the split-impulse
// push-out may give bodies placed touching. Contacts with e = 0 and friction only take energy,
// and the semi-implicit step loses ½ m g² Δt² per step of free fall; the push-out is the one
// source, lifting a body out of a penetration without doing work on it.
double slop_energy(const World& world);

// The reader's message for a scene written out as a file, or "(accepted)".
std::string refusal(const Scene& scene);

}  // namespace lamina
