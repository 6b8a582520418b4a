// A hinge stopped by an angle limit, chapter 3's other inequality row (eq. 3-17..3-22 for an
// angle): a bar pinned to the world swings down and is stopped 0.5 rad past hanging, drawn with
// its limit; beside it the sign diagram (Fig 3-3) of the limit row's (λ, W).
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch3 {

tutorial::SceneFactory angle_limit_scene();

}  // namespace lamina::ch3
