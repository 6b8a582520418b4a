// λ sweep by sweep: what PGS and the block solver have after n sweeps of one step's MLCP,
// measured against the exact answer (Lemke, constraints/exact_mlcp.h). The frames step
// heavy-on-light:1000 by `islands` and show, for each step, the error of each after 1 to 1000
// sweeps from λ = 0; lambda_error.png plots it sweep by sweep for a
// resting step of heavy-on-light:1000 and of vertical-stack:20.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch6 {

tutorial::SceneFactory sweeps_scene();

}  // namespace lamina::ch6
