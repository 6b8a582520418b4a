// Fig 3-2 and Fig 3-3: a box that may leave the incline, (x − p)·N ≥ 0 (eq. 3-17..3-22). Thrown
// off the line, it flies free (λ = 0, W > 0), lands (λ > 0, W = 0) and slides on (λ = m g cos θ);
// beside it, the text's sign diagram of (λ, W) with every step's pair.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch3 {

tutorial::SceneFactory one_sided_incline_scene();

}  // namespace lamina::ch3
