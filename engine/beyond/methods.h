// Every method a World can step with, chosen by name (`--solver NAME`, a scene's "solver" key,
// `lamina solvers`): the text's own and `pgs` (contact/solvers.h, chapters 4–5), and chapter 6's,
// which take steps 5–7 their own way through the World's StepMethod seam:
//
//   block    PGS with two-point manifolds solved as 2 × 2 blocks (block_method.h)
//   exact    every island's MLCP solved exactly by pivoting (exact_method.h)
//   soft-step  Box2D v3's substepped soft step (soft_step.h)
//   islands  Lamina's own: per island, exact, substepped exact, or PGS (island_method.h); the
//            default of `lamina run` and of scene files
#pragma once

#include <string>
#include <vector>

#include "contact/solvers.h"
#include "contact/world.h"

namespace lamina {

// The method of a scene file without a "solver" and of `lamina run` without `--solver`.
inline const char* const default_method = "islands";

// Every method, in a fixed order: `lamina solvers` prints this.
const std::vector<SolverInfo>& method_list();

// The settings of the named method: `base` with its switches (with_solver's) and, for chapter
// 6's methods, the StepMethod that takes steps 5–7. Throws std::invalid_argument naming the
// methods there are for a name that is none of them.
WorldSettings with_method(WorldSettings base, const std::string& name);

}  // namespace lamina
