// The oblique projection that draws a frame's 3D items (render/oblique.h): where a point of
// space lands on the x–y plane, in metres and then in pixels, and that the renderer draws a 3D
// point there.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "render/backend.h"
#include "render/renderer.h"

namespace {

using namespace lamina::render;
using lamina::Vec2;
using lamina::Vec3;

constexpr double eps = std::numeric_limits<double>::epsilon();

std::array<std::uint8_t, 3> rgb(Colour c) { return {c.r, c.g, c.b}; }

}  // namespace

TEST_SUITE("ObliqueProjection") {
  TEST_CASE("the cabinet default draws the unit z vector at 225°, half length: (−√2/4, −√2/4)") {
    // (x, y, z) → (x + ½ cos 225° z, y + ½ sin 225° z) with z = 1. Tolerance 2 ε: 5π/4 is
    // rounded to a double (an error below 2.3e-16 rad, which moves cos and sin by at most that)
    // and cos and sin round their results by half a unit (0.6e-16); halving is exact.
    const ObliqueProjection cabinet;
    const Vec2 z = cabinet.project(Vec3::UnitZ());
    CHECK(std::abs(z.x() + std::sqrt(2.0) / 4.0) <= 2 * eps);
    CHECK(std::abs(z.y() + std::sqrt(2.0) / 4.0) <= 2 * eps);
    // Its length on the drawing is the stated scale, ½ (the same rounding, squared and summed).
    CHECK(std::abs(z.norm() - 0.5) <= 2 * eps);
  }

  TEST_CASE("a cavalier projection at 30° draws the unit z vector at (√3/2, ½), full length") {
    const ObliqueProjection cavalier{M_PI / 6.0, 1.0};
    const Vec2 z = cavalier.project(Vec3::UnitZ());
    // Tolerance 2 ε, as above: the rounding of π/6 and of cos and sin.
    CHECK(std::abs(z.x() - std::sqrt(3.0) / 2.0) <= 2 * eps);
    CHECK(std::abs(z.y() - 0.5) <= 2 * eps);
    // Along +x at half length the numbers are exact: cos 0 = 1, sin 0 = 0.
    CHECK(ObliqueProjection{0.0, 0.5}.project(Vec3(0.0, 0.0, 3.0)) == Vec2(1.5, 0.0));
  }

  TEST_CASE("x and y are drawn as they are: a planar point lands where the 2D items put it") {
    // Exact: with z = 0 the z term is an exact zero, and adding it changes nothing.
    const ObliqueProjection cabinet;
    CHECK(cabinet.project(Vec3::UnitX()) == Vec2(1.0, 0.0));
    CHECK(cabinet.project(Vec3::UnitY()) == Vec2(0.0, 1.0));
    CHECK(cabinet.project(Vec3(-2.75, 0.125, 0.0)) == Vec2(-2.75, 0.125));
  }

  TEST_CASE("a point lands at its x, y plus z times the drawn unit z vector (the map is linear)") {
    // Expected: p.x e_x + p.y e_y + p.z project(e_z), the definition; tolerance 4 ε |p| for the
    // one product and sum per coordinate. 1000 points from a seeded generator.
    std::mt19937 rng(1501);
    std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
    const ObliqueProjection cabinet;
    const Vec2 z = cabinet.project(Vec3::UnitZ());
    for (int i = 0; i < 1000; ++i) {
      const Vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
      const Vec2 expected = p.head<2>() + p.z() * z;
      CHECK((cabinet.project(p) - expected).norm() <= 4 * eps * p.norm());
    }
  }

  TEST_CASE("in pixels the unit z vector points down and to the left of its origin") {
    // A camera of 100 px/m with the world origin at pixel (640, 360): the tip of z lands
    // 100 · √2/4 = 35.355 px left of and below the origin (pixel y grows downwards).
    // Tolerance 1e-12 px: the 2 ε of the projection times 100 px/m, plus the camera's sums.
    const Camera camera(Vec2::Zero(), 100.0, Vec2(640.0, 360.0));
    const Vec2 tip = camera.to_pixels(ObliqueProjection{}.project(Vec3::UnitZ()));
    const double offset = 100.0 * std::sqrt(2.0) / 4.0;
    CHECK(std::abs(tip.x() - (640.0 - offset)) <= 1e-12);
    CHECK(std::abs(tip.y() - (360.0 + offset)) <= 1e-12);
  }

  TEST_CASE("the projection says what it is") {
    CHECK(ObliqueProjection{}.description() == "cabinet projection: z drawn at 225°, × 0.5");
    CHECK(ObliqueProjection{M_PI / 6.0, 1.0}.description() ==
          "cavalier projection: z drawn at 30°, × 1");
  }

  TEST_CASE("a rendered 3D point is drawn where the projection puts it, not at its x, y") {
    // A point at (0, 0, 2) m under a cavalier projection at 0°: drawn at (2, 0) m, which the
    // camera puts at pixel (840, 360). Exact colours: the point's disc is 6 px in radius at
    // 1280 × 720, so the pixel under its centre is covered by the fill only, and nothing is
    // drawn at the origin's pixel (640, 360), which keeps the cleared background.
    const auto context = open_context(default_backend());
    const FrameSize size{1280, 720};
    Renderer renderer(*context, size);
    Frame frame;
    frame.projection = {0.0, 1.0};
    frame.points3.push_back({Vec3(0.0, 0.0, 2.0), palette::vermillion, ""});
    const Camera camera(Vec2::Zero(), 100.0, Vec2(640.0, 360.0));
    const Image image = renderer.render(frame, camera, Overlays{});
    CHECK(image.pixel(840, 360) == rgb(palette::vermillion));
    CHECK(image.pixel(640, 360) == rgb(palette::background));
  }
}
