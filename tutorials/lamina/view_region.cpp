#include "lamina/view_region.h"

#include <algorithm>
#include <optional>

#include "lamina/signals.h"
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

// What the frames show of the region `swept`: it, the static bodies near it, and a margin.
render::Rect view_of(const Scene& scene, const World& world, const Aabb& swept) {
  return padded(with_static_near(scene, world, swept, grown(swept, margin_of(swept))));
}

// A camera can fit it: its corners and its size are finite (a finite size needs both).
bool is_finite(const render::Rect& view) { return view.size().allFinite(); }

}  // namespace

render::Rect view_region(const Simulation& simulation, long steps) {
  const Scene& scene = simulation.scene();
  World world = build_world(scene, simulation.world().settings());
  std::optional<Aabb> swept = bodies_box(scene, world, false);
  if (!swept) {
    const std::optional<Aabb> fixed = bodies_box(scene, world, true);
    return padded(fixed.value_or(Aabb{Vec2(-1.0, -1.0), Vec2(1.0, 1.0)}));
  }
  render::Rect view = view_of(scene, world, *swept);
  for (long step = 0; step < steps; ++step) {
    if (const int signal = stop_signal()) {
      throw stopped_by(signal, simulation.origin(),
                       "before step 1, while fitting the frames' view; nothing written");
    }
    world.step();
    if (first_non_finite_body(world)) break;  // the run diverges here and will say so
    const Aabb wider = *bodies_box(scene, world, false, swept);
    const render::Rect wider_view = view_of(scene, world, wider);
    if (!is_finite(wider_view)) break;  // bodies past ~1e307 m: later frames show less
    swept = wider;
    view = wider_view;
  }
  return view;
}

}  // namespace lamina::cli
