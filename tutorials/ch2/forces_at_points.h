// Fig 2-1: forces F0, F1, F2 applied at points x0, x1, x2 of a body add up to the force
// F = Σ F_i and the torque τ = Σ (x_i − x) × F_i about its centre of mass (eq. 1-31..1-33),
// which then move it (eq. 2-3, 2-4).
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch2 {

tutorial::SceneFactory forces_at_points_scene();

}  // namespace lamina::ch2
