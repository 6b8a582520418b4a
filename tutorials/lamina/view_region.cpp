#include "lamina/view_region.h"

#include <algorithm>
#include <optional>

#include "scene/scene_world.h"

namespace lamina::cli {
namespace {

constexpr double least_margin = 0.5;       // m around what is shown, at least
constexpr double relative_margin = 0.1;    // of the region's larger side

Aabb merged(const std::optional<Aabb>& a, const Aabb& b) {
  if (!a) return b;
  return {a->min.cwiseMin(b.min), a->max.cwiseMax(b.max)};
}

Aabb grown(const Aabb& box, double margin) {
  const Vec2 m(margin, margin);
  return {box.min - m, box.max + m};
}

Aabb body_box(const World& world, int i) { return bounding_box(world.shape(i), planar_pose(world.bodies()[i])); }

// The union of the boxes of the bodies whose static flag is `fixed`, now.
std::optional<Aabb> bodies_box(const Scene& scene, const World& world, bool fixed,
                               std::optional<Aabb> region = std::nullopt) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].is_static == fixed) region = merged(region, body_box(world, static_cast<int>(i)));
  }
  return region;
}

// The static bodies' boxes clipped to `near`, added to `region`.
Aabb with_static_near(const Scene& scene, const World& world, Aabb region, const Aabb& near) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Aabb box = body_box(world, static_cast<int>(i));
    if (!scene.bodies[i].is_static || !box.overlaps(near)) continue;
    region = merged(region, Aabb{box.min.cwiseMax(near.min), box.max.cwiseMin(near.max)});
  }
  return region;
}

double margin_of(const Aabb& box) {
  return std::max(least_margin, relative_margin * (box.max - box.min).maxCoeff());
}

render::Rect padded(const Aabb& box) {
  const Aabb p = grown(box, margin_of(box));
  return {p.min, p.max};
}

}  // namespace

render::Rect view_region(const Scene& scene, const WorldSettings& settings, long steps) {
  World world = build_world(scene, settings);
  std::optional<Aabb> swept = bodies_box(scene, world, false);
  for (long step = 0; swept && step < steps; ++step) {
    world.step();
    swept = bodies_box(scene, world, false, swept);
  }
  if (!swept) {
    const std::optional<Aabb> fixed = bodies_box(scene, world, true);
    return padded(fixed.value_or(Aabb{Vec2(-1.0, -1.0), Vec2(1.0, 1.0)}));
  }
  return padded(with_static_near(scene, world, *swept, grown(*swept, margin_of(*swept))));
}

}  // namespace lamina::cli
