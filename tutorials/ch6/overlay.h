// One scene of chapter 6's table, every contender's run of it drawn on one picture: each
// contender's bodies translucent in its own colour (the legend names them), the static bodies
// once in grey, and a panel with what each has reached so far. Its plot over time (overlap,
// sway, stretch, apex) and, for the chain, the energy, are written beside the frames.
#pragma once

#include "app/harness/tutorial.h"
#include "ch6/lab.h"

namespace lamina::ch6 {

tutorial::SceneFactory overlay_scene(const TableScene& scene);

}  // namespace lamina::ch6
