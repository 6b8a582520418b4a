#include "render/mesh.h"

namespace lamina::render {

void Mesh::add(const Vec2& p, const Vec2& uv, Colour colour) {
  vertices_.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()),
                       static_cast<float>(uv.x()), static_cast<float>(uv.y()), colour});
}

void Mesh::triangle(const Vec2& a, const Vec2& b, const Vec2& c, Colour colour) {
  add(a, solid_uv_, colour);
  add(b, solid_uv_, colour);
  add(c, solid_uv_, colour);
}

void Mesh::glyph(const Rect& pixels, const Rect& uv, Colour colour) {
  const Vec2 p01(pixels.min.x(), pixels.max.y()), p10(pixels.max.x(), pixels.min.y());
  const Vec2 t01(uv.min.x(), uv.max.y()), t10(uv.max.x(), uv.min.y());
  add(pixels.min, uv.min, colour);
  add(p10, t10, colour);
  add(pixels.max, uv.max, colour);
  add(pixels.min, uv.min, colour);
  add(pixels.max, uv.max, colour);
  add(p01, t01, colour);
}

}  // namespace lamina::render
