// PNG in memory with libpng: RGB, 8 bits per channel.
#pragma once

#include <cstdint>
#include <vector>

#include "render/image.h"

namespace lamina::render {

// zlib level 6 and no row filter: for flat-colour drawings this is smaller and faster than
// libpng's adaptive filters. The same image always gives the same bytes.
std::vector<std::uint8_t> encode_png(const Image& image);

// Any PNG libpng reads, converted to 8-bit RGB. Throws std::runtime_error when it is not one.
Image decode_png(const std::vector<std::uint8_t>& bytes);

}  // namespace lamina::render
