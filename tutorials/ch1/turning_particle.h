// Fig 1-2, 1-3: a particle r_i of a body turning at ω; α is the angle between them, the particle
// runs on a circle of radius |r_i| sin α about the axis, and ṙ_i = ω × r_i, so that
// |ṙ_i| = |sin α| |r_i| |ω| (eq. 1-27, 1-28).
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch1 {

tutorial::SceneFactory turning_particle_scene();

}  // namespace lamina::ch1
