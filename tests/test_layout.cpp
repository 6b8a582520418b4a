// Layout that hides nothing (docs/slides.md): in every frame of `lamina run` on every built-in
// scene, with every overlay on, the legend lies over no body, panel or label, and no two labels
// cover each other. Checked on the boxes the painters drew (render/draw_list.h's layout), not on
// pixels; the legend's corner and the view are chosen as `lamina run` chooses them
// (FrameRenderer::place_legend, over the whole run).
#include <doctest/doctest.h>

#include <string>

#include "app/cli/frame_recording.h"
#include "app/cli/simulation.h"
#include "app/harness/render_request.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

using namespace lamina;

TEST_CASE("the legend of every built-in scene's run hides no body, panel or label") {
  tutorial::RenderRequest request;
  request.overlays = render::Overlays::parse("all");
  request.write_frames = false;
  tutorial::FrameRenderer renderer(request);
  int checked = 0;
  for (const BuiltinScene& entry : builtin_scene_list()) {
    CAPTURE(entry.name);
    Scene scene = builtin_scene(entry.name);
    const WorldSettings settings = cli::checked_settings(scene, entry.name);
    // the scene's own run, a frame every 5 steps (every frame of the default run is 5 times as
    // long and finds the same: the legend's place is fixed for the run, and the bodies move
    // less than a body's size in 5 steps at 60 Hz)
    const long steps = scene.steps;
    cli::Simulation simulation(std::move(scene), settings, entry.name);
    cli::FrameRecording recording(simulation.world(), 5, entry.name + " · " + entry.description);
    while (simulation.steps_taken() < steps) {
      const long k = simulation.steps_taken();
      const std::vector<RigidBody> at_t = simulation.world().bodies();
      simulation.step();
      if (recording.draws(k)) recording.record(k, simulation.world(), at_t);
      recording.sweep(simulation.world());
    }
    const auto& frames = recording.frames();
    const tutorial::FrameRenderer::LegendPlace place = renderer.place_legend(
        frames.size(), [&](std::size_t k) -> const render::Frame& { return frames[k].frame; },
        recording.view(simulation.world()));
    for (const cli::RecordedFrame& recorded : frames) {
      render::Frame frame = recorded.frame;
      frame.legend_corner = place.corner;
      const std::vector<std::string> overlaps = render::layout_overlaps(renderer.layout(frame, place.view));
      CAPTURE(recorded.step);
      CHECK(overlaps.empty());
      if (!overlaps.empty()) {
        MESSAGE(overlaps.front());
        break;
      }
      ++checked;
    }
  }
  MESSAGE(checked << " frames checked");
  CHECK(checked > 1000);
}

TEST_CASE("the layout check finds a legend over a body, and labels over each other") {
  // the check itself, on boxes placed by hand: it must be able to fail
  using Kind = render::LayoutBox::Kind;
  const render::Rect body{Vec2(100, 100), Vec2(200, 200)};
  CHECK(render::layout_overlaps({{Kind::body, body}, {Kind::legend, {Vec2(150, 150), Vec2(300, 300)}}}).size() == 1);
  CHECK(render::layout_overlaps({{Kind::body, body}, {Kind::legend, {Vec2(200, 100), Vec2(300, 300)}}}).empty());  // touching
  CHECK(render::layout_overlaps({{Kind::label, {Vec2(0, 0), Vec2(50, 20)}}, {Kind::label, {Vec2(40, 10), Vec2(90, 30)}}}).size() == 1);
  CHECK(render::layout_overlaps({{Kind::body, body}, {Kind::label, {Vec2(150, 150), Vec2(250, 170)}}}).empty());  // a label by its body
  CHECK(render::layout_overlaps({{Kind::panel, {Vec2(0, 0), Vec2(50, 50)}}, {Kind::legend, {Vec2(40, 40), Vec2(90, 90)}}}).size() == 1);
}

TEST_CASE("on a 320 × 180 frame the caption is cut short rather than run under the status line") {
  // `lamina run`'s caption and status on the smallest frame a slide might take: the caption,
  // at its smallest size (8 px), is still wider than the room left of the status, so it ends
  // in "…" (before, the two lines were drawn over each other)
  tutorial::RenderRequest request;
  request.size = {320, 180};
  request.write_frames = false;
  tutorial::FrameRenderer renderer(request);
  render::Frame frame;
  frame.caption = "box-on-ground · a box dropped flat from y = 2 onto the ground · solver islands";
  frame.status = "t = 1.667 s · step 100 · Δt = 1/60 s";
  const render::Rect view{Vec2(-5.0, -1.0), Vec2(5.0, 4.0)};
  const std::vector<render::LayoutBox> boxes = renderer.layout(frame, view);
  int labels = 0;
  for (const render::LayoutBox& box : boxes) labels += box.kind == render::LayoutBox::Kind::label;
  CHECK(labels == 2);  // the caption and the status are in the layout, as labels
  const std::vector<std::string> overlaps = render::layout_overlaps(boxes);
  CHECK(overlaps.empty());
}
