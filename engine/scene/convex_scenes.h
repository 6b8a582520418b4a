// The built-in scenes of polygons and capsules (docs/collision.md): a wedge ramp, a capsule pile
// and a honeycomb pyramid, listed by builtin_scenes.cpp.
#pragma once

#include <string>

#include "language/language.h"
#include "scene/scene.h"

namespace lamina::builtin {

// A static wedge of slope 35° with a hexagon tumbling down it.
Scene wedge_ramp();

// Thirty capsules dropped in six layers between two walls.
Scene capsule_pile();

// A honeycomb pyramid of regular hexagons with `n` in its base, and its description.
Scene hexagon_pyramid(double n);
std::string hexagon_pyramid_description(double n, Wording words);

}  // namespace lamina::builtin
