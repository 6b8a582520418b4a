// A World made from a Scene: the bridge from scene files to the chapter-5 engine.
#pragma once

#include "contact/world.h"
#include "scene/scene.h"

namespace lamina {

// The world settings a scene asks for: its solver's (contact/solvers.h) and its StepSettings
// (g, Δt, β, sweeps); the rest are the defaults. Throws std::invalid_argument, "solver: ...",
// for a solver name that is none.
WorldSettings world_settings(const Scene& scene);

// A body's shape about its centre of mass, as the World holds it (a polygon's vertices moved to
// be about their centroid), and where its centre of mass lies: position + R(angle) c.
struct PlacedShape {
  Shape shape;
  Vec2 centre = Vec2::Zero();  // the centre of mass, world, in m
};
PlacedShape place_shape(const BodyDescription& body);

// The scene's bodies, in order (World body i is scene.bodies[i]), with their shapes, materials,
// initial velocities and joints. Joined bodies do not collide. Throws std::invalid_argument for
// a value the engine refuses, its message led by the JSON path of the value ("joints[1]: ...").
World build_world(const Scene& scene, const WorldSettings& settings);

}  // namespace lamina
