// A bob on a rod (distance constraint) twice: with β = 0 it drifts off the circle and |C|
// grows; β = 0.2 (eq. 3-14) pulls it back. pendulum_drift.png plots |C| against t.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch3 {

tutorial::SceneFactory pendulum_scene();

}  // namespace lamina::ch3
