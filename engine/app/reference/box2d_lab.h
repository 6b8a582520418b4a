// Box2D 2.4.1's runs of chapter 6's table (app/views/beyond/solver_lab.h): the same built-in
// scene built in Box2D (box2d_scene.h: 8 velocity / 3 position iterations, its block solver,
// sleeping off), stepped in this process and measured by the same LabMeter as Lamina's runs.
//
// Box2D keeps polygons a skin b2_polygonRadius (1 cm) apart and reports a contact's separation
// between the skins; the overlap measured here is the shapes' own, −(separation + each polygon's
// skin), as Lamina's is.
#pragma once

#include <string>

#include "app/views/beyond/solver_lab.h"

namespace lamina {

inline const char* const box2d_name = "Box2D 2.4.1";

LabRun run_box2d_lab(const std::string& scene, int steps);

}  // namespace lamina
