// Chapter 4's friction ramp: a box that sticks (tan θ < μ) and one that slides at
// g (sin θ − μ cos θ), each frame showing the bodies at t with the contacts and friction step k
// solved from them (--no-cache: without the contact cache).
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch4 {

tutorial::SceneFactory friction_ramp_scene();

}  // namespace lamina::ch4
