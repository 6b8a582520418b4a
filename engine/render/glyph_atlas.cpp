#include "render/glyph_atlas.h"

#include <algorithm>
#include <stdexcept>

namespace lamina::render {
namespace {

constexpr int padding = 1;  // empty texels around each glyph, so neighbours never bleed in

}  // namespace

GlyphAtlas::GlyphAtlas() : texels_(static_cast<std::size_t>(size) * size, 0) {
  // The white block: a 2 × 2 square at the origin, sampled at its centre.
  for (int y = 0; y < 2; ++y) std::fill_n(texels_.begin() + y * size, 2, std::uint8_t{255});
  shelf_x_ = 2 + padding;
  shelf_height_ = 2;
  dirty_end_ = 2;
}

Rect GlyphAtlas::add(int width, int height, const std::uint8_t* bitmap, int pitch) {
  if (shelf_x_ + width + padding > size) {
    shelf_y_ += shelf_height_ + padding;
    shelf_x_ = 0;
    shelf_height_ = 0;
  }
  if (shelf_y_ + height + padding > size || width + padding > size) {
    throw std::length_error("glyph atlas is full: the frame size asks for too large text");
  }
  const int x = shelf_x_, y = shelf_y_;
  for (int row = 0; row < height; ++row) {
    std::copy_n(bitmap + static_cast<std::ptrdiff_t>(row) * pitch, width,
                texels_.begin() + static_cast<std::ptrdiff_t>(y + row) * size + x);
  }
  shelf_x_ += width + padding;
  shelf_height_ = std::max(shelf_height_, height);
  dirty_first_ = dirty_first_ == dirty_end_ ? y : std::min(dirty_first_, y);
  dirty_end_ = std::max(dirty_end_, y + height);
  return {Vec2(x, y) / size, Vec2(x + width, y + height) / size};
}

}  // namespace lamina::render
