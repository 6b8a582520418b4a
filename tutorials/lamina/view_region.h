// The world region a run's frames show, fitted once so every frame has the same scale.
#pragma once

#include "lamina/simulation.h"
#include "render/camera.h"

namespace lamina::cli {

// Everything the dynamic bodies of a simulation that has not stepped yet sweep over `steps`
// steps (found by running its scene once beforehand: the engine is deterministic, so the run
// that renders goes the same way), with the parts of static bodies near them (the ground
// beneath, a ramp, a pivot) and a margin. Only static bodies: all of them. No bodies: a few
// metres about the origin. A run that diverges is swept up to the step before, where the real
// run stops; one whose bodies fly past what doubles can frame (~1e307 m) up to the step before
// that. SIGINT or SIGTERM stops this with RunStopped (signals.h).
render::Rect view_region(const Simulation& simulation, long steps);

}  // namespace lamina::cli
