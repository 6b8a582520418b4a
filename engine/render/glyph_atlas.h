// One greyscale texture that holds every glyph drawn so far, plus a white block for solid fills.
#pragma once

#include <cstdint>
#include <vector>

#include "render/camera.h"

namespace lamina::render {

class GlyphAtlas {
 public:
  static constexpr int size = 2048;  // width and height, in texels (a power of two: exact uv)

  GlyphAtlas();

  // Copies a w × h coverage bitmap (rows `pitch` bytes apart) into a free spot and returns the
  // spot in atlas coordinates (0..1). Throws std::length_error when the atlas is full.
  Rect add(int width, int height, const std::uint8_t* bitmap, int pitch);

  // The atlas coordinate of a white texel: solid triangles sample it.
  Vec2 solid_uv() const { return Vec2(1.0, 1.0) / size; }

  const std::vector<std::uint8_t>& texels() const { return texels_; }
  // Rows [first, end) changed since the last mark_uploaded(); empty when first == end.
  int dirty_first() const { return dirty_first_; }
  int dirty_end() const { return dirty_end_; }
  void mark_uploaded() { dirty_first_ = dirty_end_ = 0; }

 private:
  std::vector<std::uint8_t> texels_;  // size × size coverage, row 0 first
  int shelf_x_ = 0;                   // next free column on the current shelf
  int shelf_y_ = 0;                   // top row of the current shelf
  int shelf_height_ = 0;              // tallest glyph on the current shelf
  int dirty_first_ = 0;
  int dirty_end_ = 0;
};

}  // namespace lamina::render
