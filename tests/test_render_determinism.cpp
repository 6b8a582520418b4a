// Determinism: the same frame always gives the same pixels, and the pipelined writer (several
// encoder threads) always gives the same files, whatever the threads' timing.
#include <doctest/doctest.h>

#include <fstream>
#include <iterator>

#include "render/backend.h"
#include "render/frame_writer.h"
#include "render/png_codec.h"
#include "render/renderer.h"
#include "render_test_frame.h"

namespace {

using namespace lamina::render;
using lamina::Vec2;
namespace fs = std::filesystem;

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A short sequence: the test frame with its box turning, every overlay on.
std::vector<Image> render_sequence(Renderer& renderer) {
  std::vector<Image> images;
  for (int i = 0; i < 4; ++i) {
    Frame frame = testing::full_frame();
    frame.bodies[0].angle += 0.2 * i;
    images.push_back(
        renderer.render(frame, testing::test_camera(Overlays::all()), Overlays::all()));
  }
  return images;
}

void write_sequence(const std::vector<Image>& images, const fs::path& folder) {
  FrameWriter writer(3, 2);
  for (std::size_t i = 0; i < images.size(); ++i) {
    writer.submit(folder / ("frame_" + std::to_string(i) + ".png"), images[i]);
  }
  writer.finish();
}

}  // namespace

TEST_SUITE("RenderDeterminism") {
  TEST_CASE("the same frame rendered twice gives identical pixels") {
    const auto context = open_context(default_backend());
    Renderer first(*context, testing::test_size);
    const std::vector<Image> a = render_sequence(first);
    const std::vector<Image> b = render_sequence(first);
    Renderer second(*context, testing::test_size);  // a new renderer: new atlas, new buffers
    const std::vector<Image> c = render_sequence(second);
    for (std::size_t i = 0; i < a.size(); ++i) {
      CAPTURE(i);
      CHECK(a[i].rgb == b[i].rgb);  // exact, byte for byte
      CHECK(a[i].rgb == c[i].rgb);
    }
  }

  TEST_CASE("two runs of the pipelined writer give byte-identical PNG files") {
    const auto context = open_context(default_backend());
    Renderer renderer(*context, testing::test_size);
    const std::vector<Image> images = render_sequence(renderer);
    const testing::ScratchFolder first("determinism-1"), second("determinism-2");
    write_sequence(images, first.path());
    write_sequence(render_sequence(renderer), second.path());
    for (std::size_t i = 0; i < images.size(); ++i) {
      const std::string name = "frame_" + std::to_string(i) + ".png";
      CAPTURE(name);
      const std::vector<std::uint8_t> bytes = read_bytes(first.path() / name);
      CHECK(bytes == read_bytes(second.path() / name));
      CHECK(decode_png(bytes).rgb == images[i].rgb);
    }
  }
}
