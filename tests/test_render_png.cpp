// The PNG codec and what a rendered frame looks like once written: its size, and known colours
// at known places (the background at the corners, a body's fill inside it).
#include <doctest/doctest.h>

#include <stdexcept>

#include "render/backend.h"
#include "render/png_codec.h"
#include "render/renderer.h"
#include "render_test_frame.h"

namespace {

using namespace lamina::render;
using lamina::Vec2;
using testing::test_size;

// A 37 × 23 image whose every pixel differs from its neighbours.
Image gradient() {
  Image image{37, 23, {}};
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      image.rgb.insert(image.rgb.end(),
                       {static_cast<std::uint8_t>(7 * x), static_cast<std::uint8_t>(11 * y),
                        static_cast<std::uint8_t>(x ^ y)});
    }
  }
  return image;
}

std::array<std::uint8_t, 3> rgb(Colour c) { return {c.r, c.g, c.b}; }

}  // namespace

TEST_SUITE("PngCodec") {
  TEST_CASE("an encoded image decodes to the same pixels (lossless round trip)") {
    const Image image = gradient();
    const std::vector<std::uint8_t> bytes = encode_png(image);
    const std::uint8_t signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    CHECK(std::equal(std::begin(signature), std::end(signature), bytes.begin()));
    const Image decoded = decode_png(bytes);
    CHECK(decoded.width == image.width);
    CHECK(decoded.height == image.height);
    CHECK(decoded.rgb == image.rgb);  // exact: PNG is lossless
  }

  TEST_CASE("the same image always encodes to the same bytes") {
    CHECK(encode_png(gradient()) == encode_png(gradient()));
  }

  TEST_CASE("bytes that are not a PNG are refused") {
    CHECK_THROWS_AS(decode_png({'n', 'o', 't', ' ', 'a', ' ', 'p', 'n', 'g'}), std::runtime_error);
  }

  TEST_CASE(
      "a rendered frame has the frame size, the background at its corners, a body's fill "
      "inside the body") {
    const auto context = open_context(default_backend());
    Renderer renderer(*context, test_size);
    const Overlays none;
    const Camera camera = testing::test_camera(none);
    const Frame frame = testing::full_frame();
    const Image image = decode_png(encode_png(renderer.render(frame, camera, none)));
    REQUIRE(image.width == test_size.width);
    REQUIRE(image.height == test_size.height);
    // Exact: the corners lie in the margin, where nothing is drawn over the cleared background.
    CHECK(image.pixel(0, 0) == rgb(palette::background));
    CHECK(image.pixel(test_size.width - 1, 0) == rgb(palette::background));
    CHECK(image.pixel(0, test_size.height - 1) == rgb(palette::background));
    // Exact: a point well inside the box, off its rotation mark, is covered by the fill only.
    const Body& box = frame.bodies[0];
    const Vec2 inside = camera.to_pixels(box.centre + Vec2(-0.25, 0.25));
    CHECK(image.pixel(static_cast<int>(inside.x()), static_cast<int>(inside.y())) == rgb(box.fill));
  }
}
