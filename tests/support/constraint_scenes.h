// Chapter-3 scenes shared by the constraint tests (incline, pendulum, joints, constraint forces,
// the constrained step and the dense reference), on planar scenes (x–y, y up).
#pragma once

#include <vector>

#include "constraints/constraint.h"
#include "motion/rigid_body.h"

namespace lamina {

// |value − expected| / |expected|.
double relative_error(double value, double expected);

// A rod 1 m × 5 cm (m = 1 kg) pinned at one end to the world origin by a revolute joint, its
// centre at `angle` from +x. Appends the rod to the bodies and returns the joint.
ConstraintList pinned_rod(std::vector<RigidBody>& bodies, double angle);

// Three boxes in a chain pinned to the world, a rope from the last one to the world, a limit on
// the first joint's angle, a box on an incline, and a static body pinned to a fifth box.
ConstraintList mixed_scene(std::vector<RigidBody>& bodies);

// mixed_scene with random velocities and forces on every dynamic body, from a seed.
ConstraintList shaken_mixed_scene(std::vector<RigidBody>& bodies, unsigned seed);

}  // namespace lamina
