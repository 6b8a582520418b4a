// Four links on revolute joints, pinned to the world, released straight at 1.2 rad. Each
// frame gives PGS's residual ‖W‖ (eq. 3-23, 3-24) from last step's λ and from zero, and
// pgs_residual.png plots ‖W‖ per sweep for both at one step.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch3 {

tutorial::SceneFactory chain_scene();

}  // namespace lamina::ch3
