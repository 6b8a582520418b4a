// A rendered frame in memory: 8-bit RGB, rows top to bottom, no padding.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace lamina::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width × height × 3 bytes, row 0 is the top row
  std::vector<std::uint8_t> alpha{};  // width × height opacities; empty: opaque (every frame but
                                    // those with --background transparent)

  std::array<std::uint8_t, 3> pixel(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

}  // namespace lamina::render
