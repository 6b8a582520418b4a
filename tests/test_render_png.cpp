// The PNG codec and what a rendered frame looks like once written: its size, and known colours
// at known places (the background at the corners, a body's fill inside it).
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "render/backend.h"
#include "render/png_codec.h"
#include "render/renderer.h"
#include "render/vector_output.h"
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

  TEST_CASE("a transparent frame has nothing where nothing is drawn, and over the paper it is the opaque frame") {
    const auto context = open_context(default_backend());
    Renderer renderer(*context, test_size);
    const Overlays all = Overlays::parse("all");
    const Camera camera = testing::test_camera(all);
    const Frame frame = testing::full_frame();
    const Image opaque = renderer.render(frame, camera, all);
    renderer.set_background(Background{true, {}});
    // through the PNG codec, as a file would hold it (RGBA)
    const Image clear = decode_png(encode_png(renderer.render(frame, camera, all)));
    REQUIRE(clear.alpha.size() == static_cast<std::size_t>(test_size.width) * test_size.height);
    CHECK(opaque.alpha.empty());
    // Exact: the corners lie in the margin, where nothing is drawn: opacity 0.
    CHECK(clear.alpha.front() == 0);
    CHECK(clear.alpha.back() == 0);
    // Exact: inside the box only its opaque fill is drawn.
    const Body& box = frame.bodies[0];
    const Vec2 inside = camera.to_pixels(box.centre + Vec2(-0.25, 0.25));
    const std::size_t at = static_cast<std::size_t>(inside.y()) * test_size.width + static_cast<std::size_t>(inside.x());
    CHECK(clear.alpha[at] == 255);
    CHECK(clear.pixel(static_cast<int>(inside.x()), static_cast<int>(inside.y())) == rgb(box.fill));
    // Composited over the paper colour (straight alpha: c a + paper (1 − a)), every pixel is the
    // opaque frame's, to 3 of 255 per channel: the colour taken back from colour × opacity loses
    // up to 255 / (2 a) before it is multiplied by a again (≤ 1), plus each rounding (≤ 1 each).
    int worst = 0;
    long translucent = 0;
    for (int y = 0; y < test_size.height; ++y) {
      for (int x = 0; x < test_size.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * test_size.width + x;
        const double a = clear.alpha[i] / 255.0;
        translucent += clear.alpha[i] > 0 && clear.alpha[i] < 255;
        const auto c = clear.pixel(x, y), o = opaque.pixel(x, y);
        const std::array<std::uint8_t, 3> paper = rgb(palette::background);
        for (int k = 0; k < 3; ++k) {
          const double over = c[k] * a + paper[k] * (1.0 - a);
          worst = std::max(worst, static_cast<int>(std::lround(std::abs(over - o[k]))));
        }
      }
    }
    MESSAGE("transparent over the paper against opaque: at most " << worst << " of 255 apart; "
                                                                  << translucent << " translucent pixels");
    CHECK(translucent > 1000);  // edges, text and the panels' 90 % white: the case is exercised
    CHECK(worst <= 3);
  }
}
