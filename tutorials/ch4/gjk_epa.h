// Beyond the text, chapter 4: GJK and EPA (engine/contact/gjk.h) step by step on one pair of
// polygons, A a hexagon and B a triangle, with the engine's own numbers (docs/collision.md).
//   gjk  A and B apart: GJK's simplex on D = B − A, one frame per iteration (gjk_scene.h).
//   epa  B moved into A: EPA's polytope grown from GJK's triangle (epa_scene.h).
// The pair and the figure both scenes draw it in: pair_figure.h.
#pragma once

#include "ch4/epa_scene.h"
#include "ch4/gjk_scene.h"
