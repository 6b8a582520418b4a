// Fig 3-1: a box held on a line through p with normal N (eq. 3-1..3-4); the constraint
// force λN cancels the normal part of m g, and the box slides with g sin θ.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch3 {

tutorial::SceneFactory incline_scene();

}  // namespace lamina::ch3
