// Box2D v3, the engine a user would pick today, on the same pyramids: the performance peer of
// issue 19. Not a Debian package and never needed to build or test Lamina: built only when the
// benchmarks are configured with -DLAMINA_BOX2D_V3_DIR=<its source> (its public repository at
// tag v3.1.1, docs/performance.md), which defines LAMINA_HAVE_BOX2D_V3.
//
//   scene   the same Scene as Lamina's and Box2D 2.4.1's (pyramid_of): the boxes' half
//           extents, positions, densities and friction, the static ground box, Δt = 1/60
//   v3      its soft step with `substeps` substeps, one thread (no task system), sleeping and
//           continuous collision off; SIMD as its build chose (AVX2 here)
//   rows    a normal and a friction row per manifold point, solved once per substep (and
//           relaxed once more), counted from its contact data
#pragma once

#include "benchmarks/pyramid_runs.h"

namespace lamina {

// Box2D v3's substeps per step in the table.
inline constexpr int box2d_v3_substeps = 4;

// Box2D v3 on the pyramid of boxes of that base, measured as the other engines are.
PyramidRun run_box2d_v3_pyramid(int base, int substeps = box2d_v3_substeps);

// "3.1.1": the version of the Box2D v3 built in.
std::string box2d_v3_version();

}  // namespace lamina
