// The frames/s benchmark of docs/rendering.md: 210 spinning boxes thrown up and falling back
// (chapter-2 motion), every frame drawn with velocities and centres of mass, encoded and
// written. The harness prints the end-to-end rate: physics + render + encode + write.
//   render_benchmark --frames 240 --out /tmp/lamina-bench
#include <random>

#include "app/views/motion/body_view.h"
#include "app/harness/tutorial.h"
#include "motion/integrator.h"

namespace {

using namespace lamina;

constexpr int columns = 21, rows = 10;       // 210 boxes
constexpr double spacing = 0.6;              // between box centres, in m
const Vec2 half_extents(0.2, 0.14);  // in m
const Vec3 gravity(0.0, -9.8, 0.0);

class ThrownBoxes : public tutorial::Scene {
 public:
  ThrownBoxes() {
    std::mt19937 random(2011);  // seeded: the same boxes every run
    std::uniform_real_distribution<double> spread(-1.0, 1.0);
    for (int i = 0; i < columns * rows; ++i) {
      const Vec3 x((i % columns) * spacing, (i / columns) * spacing, 0.0);
      RigidBody box = box_body(1.0, half_extents.x(), half_extents.y(), x, spread(random));
      box.v = Vec3(0.5 * spread(random), 9.0 + spread(random), 0.0);
      box.angular_velocity = Vec3(0.0, 0.0, 4.0 * spread(random));
      bodies_.push_back(box);
    }
  }

  tutorial::SceneInfo info() const override {
    return {
        "thrown_boxes", 1.0 / 60.0, 120, 1, {Vec2(-1.0, -1.0), Vec2(13.0, 11.0)}};
  }

  void step() override { step_unconstrained(bodies_, gravity, 1.0 / 60.0); }

  void draw(render::Frame& frame) const override {
    frame.caption = "Benchmark: 210 boxes in flight (chapter-2 motion)";
    frame.velocity_scale = 0.05;
    for (const RigidBody& b : bodies_) {
      frame.bodies.push_back(
          view::box_view(b, half_extents, tint(render::palette::sky_blue, 0.35)));
    }
  }

  tutorial::Explanation explain() const override {
    return {{"first box", {{"x", "2-5", "centre of mass", tutorial::json_of(bodies_[0].x), "m"}}}};
  }

 private:
  std::vector<RigidBody> bodies_;
};

}  // namespace

int main(int argc, char** argv) {
  const tutorial::TutorialInfo info{"render_benchmark",
                                    "bench",
                                    "Frames/s of physics + render + encode + write, 210 boxes",
                                    {render::Overlay::velocities, render::Overlay::centres}};
  return tutorial::run_tutorial(argc, argv, info, {tutorial::scene<ThrownBoxes>()});
}
