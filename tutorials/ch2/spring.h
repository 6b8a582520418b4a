// The text's "implicit is more stable", shown: a disc on a spring, stepped by explicit Euler on
// the left and by the text's semi-implicit step (eq. 2-5) on the right. Explicit Euler multiplies
// the energy by exactly 1 + ω²Δt² every step, so the swing grows as (1 + ω²Δt²)^(n/2); the
// semi-implicit step keeps it within about ωΔt of the start. spring_energy.png plots E/E₀ of
// both with the analytic (1 + ω²Δt²)ⁿ.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch2 {

tutorial::SceneFactory spring_scene();

}  // namespace lamina::ch2
