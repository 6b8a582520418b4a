// Box2D 2.4.1, the behavioural reference, built from the same Scene as Lamina.
//
// Used by the tests, the benchmarks and chapter 6's table (06_beyond_the_text): no stage of the
// engine links Box2D, only this room of the application does.
#pragma once

#include <memory>
#include <vector>

#include <box2d/box2d.h>

#include "scene/scene.h"

namespace lamina {

// How Lamina's comparisons run Box2D: 8 velocity / 3 position iterations, continuous collision
// off (Lamina has none), sleeping off unless asked (a sleeping body reports no motion at all).
struct Box2dSettings {
  int velocity_iterations = 8;
  int position_iterations = 3;
  bool allow_sleeping = false;
};

struct Box2dScene {
  std::unique_ptr<b2World> world;
  std::vector<b2Body*> bodies;  // in the Scene's body order
  Box2dSettings settings;
  float dt = 1.0f / 60.0f;

  void step() { world->Step(dt, settings.velocity_iterations, settings.position_iterations); }
};

// Box2D's world for the scene: the same bodies, shapes, densities, friction, restitution and
// joints, in the same order. Throws std::invalid_argument for a capsule (Box2D 2.4.1 has none).
Box2dScene make_box2d_scene(const Scene& scene, const Box2dSettings& settings = {});

}  // namespace lamina
