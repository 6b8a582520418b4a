// Beyond the text, chapter 4: GJK (engine/contact/gjk.h) step by step on the pair of polygons of
// pair_figure.h, A and B apart, with the engine's own numbers (docs/collision.md). Left: the
// shapes, the vertices a_i and b_j of the support point just added. Right: their Minkowski
// difference D = B − A (the hull of every b_j − a_i) about the origin O, with GJK's simplex, its
// point w nearest O, the search direction −w and the support point s_D(−w). One frame per
// iteration; the last shows the distance and the closest points a, b on the shapes.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch4 {

tutorial::SceneFactory gjk_scene();

}  // namespace lamina::ch4
