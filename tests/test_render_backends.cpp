// The two GL backends, OSMesa and EGL surfaceless, draw the same frame to the same pixels:
// both are Mesa's llvmpipe behind the same FBO and the same drawing code.
#include <doctest/doctest.h>

#include "render/backend.h"
#include "render/renderer.h"
#include "render_test_frame.h"

namespace {

using namespace lamina::render;
using lamina::Vec2;

Image render_with(Backend backend) {
  const auto context = open_context(backend);
  Renderer renderer(*context, testing::test_size);
  return renderer.render(testing::full_frame(), testing::test_camera(Overlays::all()),
                         Overlays::all());
}

}  // namespace

TEST_SUITE("RenderBackends") {
  TEST_CASE("every built backend makes a context and draws a frame of the asked size") {
    for (const auto& built : built_backends()) {
      CAPTURE(built.first);  // (a structured binding cannot be captured in C++17: clang refuses)
      const Image image = render_with(built.second);
      CHECK(image.width == testing::test_size.width);
      CHECK(image.height == testing::test_size.height);
    }
  }

  TEST_CASE("OSMesa and EGL surfaceless give identical pixels for the same frame") {
    if (built_backends().size() < 2) {
      MESSAGE("skipped: only one backend is built (libosmesa6-dev missing)");
      return;
    }
    // One context at a time: each is made current, used and destroyed before the next.
    const Image osmesa = render_with(Backend::osmesa);
    const Image egl = render_with(Backend::egl);
    CHECK(osmesa.rgb == egl.rgb);  // exact, byte for byte
  }
}
