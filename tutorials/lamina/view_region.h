// The world region a run's frames show, fitted once so every frame has the same scale.
#pragma once

#include "contact/world.h"
#include "render/camera.h"
#include "scene/scene.h"

namespace lamina::cli {

// Everything the dynamic bodies sweep over `steps` steps (found by running the scene once
// beforehand: the engine is deterministic, so the run that renders goes the same way), with
// the parts of static bodies near them (the ground beneath, a ramp, a pivot) and a margin.
// Only static bodies: all of them. No bodies: a few metres about the origin.
render::Rect view_region(const Scene& scene, const WorldSettings& settings, long steps);

}  // namespace lamina::cli
