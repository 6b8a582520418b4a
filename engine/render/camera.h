// World (metres, y up) to pixels (origin top left, y down): a centre and a scale.
#pragma once

#include "render/frame.h"

namespace lamina::render {

// An axis-aligned rectangle: a world region in m, or an area of the frame in pixels.
struct Rect {
  Vec2 min = Vec2::Zero();
  Vec2 max = Vec2::Zero();

  Vec2 size() const { return max - min; }
  Vec2 centre() const { return 0.5 * (min + max); }
};

class Camera {
 public:
  // A given camera: world point `world_centre` lands on pixel `pixel_centre`.
  Camera(const Vec2& world_centre, double pixels_per_metre, const Vec2& pixel_centre);

  // The largest scale that shows all of `world` inside the pixel rectangle `area`, centred.
  // A sequence fits once and keeps the camera, so every frame has the same scale.
  // Throws std::invalid_argument for an empty or non-finite region.
  static Camera fit(const Rect& world, const Rect& area);

  Vec2 to_pixels(const Vec2& world) const;
  Vec2 to_world(const Vec2& pixel) const;
  double pixels_per_metre() const { return scale_; }

 private:
  Vec2 world_centre_;  // in m
  double scale_;       // pixels per metre
  Vec2 pixel_centre_;  // in pixels
};

}  // namespace lamina::render
