// Chapter 4's Fig 4-1: the geometry of one contact. A unit box (body 2) lands tilted on a wide
// fixed box (body 1); each frame draws, for the deepest point the narrow phase returned at t
// (or else a point the cache kept), the centres x1 and x2, the levers r1 and r2 to the two
// surface points p1 = x1 + r1 and p2 = x2 + r2, and body 1's outward normal n1, with the
// separation of eq. 4-1 computed from them beside the engine's.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::ch4 {

tutorial::SceneFactory contact_geometry_scene();

}  // namespace lamina::ch4
