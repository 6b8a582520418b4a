// What the tests of PGS's lanes and threads share (test_pgs_lanes.cpp, test_pgs_threads.cpp): a
// World's step reported, by `pgs`, and λ solved from its warm start, compared as bytes.
#pragma once

#include <cstddef>
#include <vector>

#include "constraints/pgs_solver.h"
#include "contact/world_report.h"
#include "scene/builtin_scenes.h"
#include "scene/scene.h"

namespace lamina {

// The bytes of a vector of doubles: equal bytes, equal bits (−0 and +0, and NaNs, told apart).
std::vector<unsigned char> bytes_of(const double* values, std::size_t count);

// The step of `scene` by `pgs` after `steps` steps, reported: its velocity MLCP and warm start,
// and its position MLCP, solved from λ = 0. pyramid:20's velocity MLCP has 1700-odd rows.
WorldReport report_after(int steps, Scene scene = builtin_scene("pyramid:20"));
// Its velocity MLCP and warm start.
StepReport mlcp_after(int steps, Scene scene = builtin_scene("pyramid:20"));

// λ after `sweeps` sweeps from the report's warm start, by `solver`.
std::vector<unsigned char> solved(PgsSolver& solver, const StepReport& step, int sweeps,
                                  Pitfalls pitfalls = {});

}  // namespace lamina
