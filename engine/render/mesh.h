// The triangles of one frame, in pixels: what the painters produce and the GPU draws.
#pragma once

#include <vector>

#include "render/camera.h"
#include "render/colour.h"

namespace lamina::render {

// One vertex as the shader reads it (attribute layout in renderer.cpp).
struct Vertex {
  float x, y;     // position, in pixels (origin top left, y down)
  float u, v;     // glyph atlas coordinates; the atlas's white texel for solid fills
  Colour colour;  // sRGB and opacity, multiplied by the atlas coverage
};

class Mesh {
 public:
  // `solid_uv` is the atlas coordinate of a white texel, used by every solid triangle.
  explicit Mesh(const Vec2& solid_uv) : solid_uv_(solid_uv) {}

  void triangle(const Vec2& a, const Vec2& b, const Vec2& c, Colour colour);
  // A textured rectangle: `pixels` on screen shows `uv` of the atlas.
  void glyph(const Rect& pixels, const Rect& uv, Colour colour);

  const std::vector<Vertex>& vertices() const { return vertices_; }

 private:
  void add(const Vec2& p, const Vec2& uv, Colour colour);

  std::vector<Vertex> vertices_;
  Vec2 solid_uv_;
};

}  // namespace lamina::render
