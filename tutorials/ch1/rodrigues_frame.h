// Fig 1-1: a vector v turned by θ about the unit axis d, drawn in the orthonormal frame a, b, d
// the text builds Rodrigues' formula in (eq. 1-4, 1-6, 1-9).
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch1 {

tutorial::SceneFactory rodrigues_frame_scene();

}  // namespace lamina::ch1
