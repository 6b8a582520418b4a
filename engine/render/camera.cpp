#include "render/camera.h"

#include <algorithm>
#include <stdexcept>

namespace lamina::render {

Camera::Camera(const Vec2& world_centre, double pixels_per_metre, const Vec2& pixel_centre)
    : world_centre_(world_centre), scale_(pixels_per_metre), pixel_centre_(pixel_centre) {}

Camera Camera::fit(const Rect& world, const Rect& area) {
  const Vec2 extent = world.size();
  if (!extent.allFinite() || extent.x() <= 0.0 || extent.y() <= 0.0) {
    throw std::invalid_argument("camera: the region to fit must have a finite, positive size");
  }
  const Vec2 room = area.size();
  const double scale = std::min(room.x() / extent.x(), room.y() / extent.y());
  return Camera(world.centre(), scale, area.centre());
}

Vec2 Camera::to_pixels(const Vec2& world) const {
  const Vec2 d = (world - world_centre_) * scale_;
  return {pixel_centre_.x() + d.x(), pixel_centre_.y() - d.y()};
}

Vec2 Camera::to_world(const Vec2& pixel) const {
  const Vec2 d = pixel - pixel_centre_;
  return world_centre_ + Vec2(d.x(), -d.y()) / scale_;
}

}  // namespace lamina::render
