// Beyond the text, chapter 4: EPA (engine/contact/gjk.h) step by step on the pair of polygons of
// pair_figure.h, B moved into A, with the engine's own numbers (docs/collision.md): GJK's last
// simplex, a triangle holding O; then per EPA iteration the polytope, its edge nearest O with
// outward normal m and distance, and s_D(m); the last frame shows the penetration normal n and
// depth on the shapes, beside the depth of the separating axis test over the polygons' edge
// normals.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch4 {

tutorial::SceneFactory epa_scene();

}  // namespace lamina::ch4
