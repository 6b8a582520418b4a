// How a World looks in a frame: its bodies' outlines, its contacts with their forces, and its
// joints, as the renderer's plain Frame (engine/render/frame.h).
#pragma once

#include <array>
#include <vector>

#include "contact/world.h"
#include "render/frame.h"
#include "scene/scene.h"

namespace lamina::cli {

// A joint's two ends as offsets r in their bodies' frames (eq. 1-25: p = x + R r).
struct JointEnds {
  std::array<int, 2> bodies{0, 0};             // World body indices
  std::array<Vec2, 2> offsets{Vec2::Zero(), Vec2::Zero()};  // r on each body, in m
};

// The scene's joints on a world that has not stepped yet (its bodies where the scene put them).
std::vector<JointEnds> joint_ends(const Scene& scene, const World& world);

// The world now: bodies, contacts (normal from body 1 into body 2, forces λ) and joints.
render::Frame world_frame(const Scene& scene, const World& world, const std::vector<JointEnds>& joints);

}  // namespace lamina::cli
