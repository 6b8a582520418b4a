#include "render/png_codec.h"

#include <png.h>

#include <csetjmp>
#include <stdexcept>
#include <string>

namespace lamina::render {
namespace {

void append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

// libpng reports errors by longjmp to this frame; it holds nothing with a destructor.
// `row`: room for one RGBA row, made by the caller (nothing here may need destroying).
bool write_rows(png_structp png, png_infop info, const Image& image,
                std::vector<std::uint8_t>* out, std::vector<std::uint8_t>& row) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, append, nullptr);
  const bool alpha = !image.alpha.empty();  // RGBA with --background transparent
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8,
               alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 6);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  const std::size_t stride = 3 * static_cast<std::size_t>(image.width);
  for (int y = 0; y < image.height; ++y) {
    if (!alpha) {
      png_write_row(png, image.rgb.data() + y * stride);
      continue;
    }
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      for (int c = 0; c < 3; ++c) row[4 * x + c] = image.rgb[3 * i + c];
      row[4 * x + 3] = image.alpha[i];
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint8_t> row(image.alpha.empty() ? 0 : 4 * static_cast<std::size_t>(image.width));
  const bool ok = info != nullptr && write_rows(png, info, image, &bytes, row);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw std::runtime_error("libpng could not encode a frame");
  return bytes;
}

Image decode_png(const std::vector<std::uint8_t>& bytes) {
  png_image header{};
  header.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&header, bytes.data(), bytes.size())) {
    throw std::runtime_error(std::string("not a PNG: ") + header.message);
  }
  const bool alpha = (header.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  header.format = alpha ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
  Image image{static_cast<int>(header.width), static_cast<int>(header.height), {}};
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(header));
  if (!png_image_finish_read(&header, nullptr, pixels.data(), 0, nullptr)) {
    throw std::runtime_error(std::string("cannot decode PNG: ") + header.message);
  }
  if (!alpha) {
    image.rgb = std::move(pixels);
    return image;
  }
  const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
  image.rgb.resize(3 * count);
  image.alpha.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = pixels[4 * i + c];
    image.alpha[i] = pixels[4 * i + 3];
  }
  return image;
}

}  // namespace lamina::render
