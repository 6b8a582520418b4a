#include "app/cli/frame_recording.h"

#include <algorithm>

#include "app/views/contact/world_view.h"

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

Aabb body_box(const World& world, std::size_t i) {
  return bounding_box(world.shape(static_cast<int>(i)), planar_pose(world.bodies()[i]));
}

// The union of the boxes of the bodies whose static flag is `fixed`, now.
std::optional<Aabb> bodies_box(const World& world, bool fixed) {
  std::optional<Aabb> region;
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    if (world.bodies()[i].is_static() == fixed) region = merged(region, body_box(world, i));
  }
  return region;
}

// The static bodies' boxes clipped to `near`, added to `region`.
Aabb with_static_near(const World& world, Aabb region, const Aabb& near) {
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const Aabb box = body_box(world, i);
    if (!world.bodies()[i].is_static() || !box.overlaps(near)) continue;
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
render::Rect view_of(const World& world, const Aabb& swept) {
  return padded(with_static_near(world, swept, grown(swept, margin_of(swept))));
}

// A camera can fit it: its corners and its size are finite (a finite size needs both).
bool is_finite(const render::Rect& view) { return view.size().allFinite(); }

}  // namespace

FrameRecording::FrameRecording(const World& world, int every, std::string caption)
    : every_(every), caption_(std::move(caption)), swept_(bodies_box(world, false)) {}

void FrameRecording::record(long step, const World& world, const std::vector<RigidBody>& at_t) {
  RecordedFrame& recorded = frames_.emplace_back(RecordedFrame{step, view::world_frame(world, at_t)});
  recorded.frame.caption = caption_;
}

void FrameRecording::sweep(const World& world) {
  if (stopped_sweeping_ || !swept_) return;
  const Aabb wider = merged(swept_, *bodies_box(world, false));
  if (!is_finite(view_of(world, wider))) {
    stopped_sweeping_ = true;  // bodies past ~1e307 m: later frames show less
    return;
  }
  swept_ = wider;
}

render::Rect FrameRecording::view(const World& world) const {
  if (swept_) return view_of(world, *swept_);
  const std::optional<Aabb> fixed = bodies_box(world, true);
  return padded(fixed.value_or(Aabb{Vec2(-1.0, -1.0), Vec2(1.0, 1.0)}));
}

}  // namespace lamina::cli
