// The pieces built-in scenes are made of (builtin_scenes.cpp, convex_scenes.cpp): the ground,
// a box, a scene of bodies and joints.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace lamina::builtin {

constexpr double half = 0.5;  // half extent of the unit box, in m

// The ground of every box-on-ground scene: a static box (half_width, 0.5) whose top is at y = 0.
BodyDescription ground(double half_width = 20.0);

// A box named `name` at `position`, turned by `angle` (rad); the unit box unless told.
BodyDescription box(const std::string& name, Vec2 position, Vec2 half_extents = {half, half},
                    double angle = 0.0);

// A scene of these bodies and joints; builtin_scene gives it its name and description.
Scene with(std::vector<BodyDescription> bodies, std::vector<JointDescription> joints = {});

}  // namespace lamina::builtin
