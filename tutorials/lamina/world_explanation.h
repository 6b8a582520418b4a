// What the World computed in its last step, in the text's terms, for `lamina run --explain`:
// each contact the solver took (eq. 4-1, 3-16) and each dynamic body after the step (eq. 2-3..2-6).
#pragma once

#include "contact/world.h"
#include "harness/explanation.h"
#include "scene/scene.h"

namespace lamina::cli {

// `report` is the last step's (empty before the first step: the bodies as the scene put them).
tutorial::Explanation world_explanation(const Scene& scene, const World& world,
                                        const WorldReport& report);

}  // namespace lamina::cli
