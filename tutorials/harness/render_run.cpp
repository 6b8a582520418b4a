// Rendering: the GL thread steps the scene and draws; encoder threads write the PNGs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <thread>

#include "harness/runs.h"
#include "output/output_file.h"
#include "render/frame_writer.h"
#include "render/renderer.h"

namespace lamina::tutorial {
namespace {

constexpr std::size_t queued_frames = 4;  // images waiting for an encoder, at most

int encoder_threads() {
  return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 4u));
}

std::string frame_name(const std::string& scene, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "_%04d.png", index);
  return scene + name;
}

// "t = 0.500 s · step 30 · Δt = 1/60 s"
std::string status_line(long step, double dt) {
  char text[96];
  const double rate = 1.0 / dt;
  if (std::abs(rate - std::round(rate)) < 1e-9) {
    std::snprintf(text, sizeof text, "t = %.3f s · step %ld · Δt = 1/%.0f s", step * dt, step,
                  rate);
  } else {
    std::snprintf(text, sizeof text, "t = %.3f s · step %ld · Δt = %.4g s", step * dt, step, dt);
  }
  return text;
}

// Renders one scene; returns the number of frames.
int render_scene(Scene& scene, const Options& o, render::Renderer& renderer,
                 render::FrameWriter& writer) {
  const SceneInfo info = scene.info();
  const int frames = o.frames.value_or(info.frames), every = o.every.value_or(info.every);
  const render::Rect area =
      render::Style::for_size(o.size).drawing_area(o.size, o.overlays.has(render::Overlay::axes));
  const render::Camera camera = render::Camera::fit(info.view, area);
  long step = 0;
  for (int f = 0; f < frames; ++f) {
    for (int k = 0; f > 0 && k < every; ++k, ++step) scene.step();
    render::Frame frame;
    scene.draw(frame);
    frame.status = status_line(step, info.time_step);
    writer.submit(o.out / frame_name(info.name, f), renderer.render(frame, camera, o.overlays));
  }
  return frames;
}

}  // namespace

void render_scenes(const TutorialInfo& info, const Options& o,
                   const std::vector<SceneFactory>& scenes) {
  prepare_output_folder(o.out);
  const auto context = render::open_context(o.backend);
  render::Renderer renderer(*context, o.size);
  render::FrameWriter writer(encoder_threads(), queued_frames);
  for (const SceneFactory& make : scenes) {
    const auto start = std::chrono::steady_clock::now();
    const auto scene = make(o);
    const int frames = render_scene(*scene, o, renderer, writer);
    writer.finish();
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    scene->write_data(o.out);
    std::printf(
        "%s: %d frames of %s, %dx%d, in %.2f s (%.1f frames/s: physics, render, "
        "encode, write) -> %s\n",
        info.name.c_str(), frames, scene->info().name.c_str(), o.size.width, o.size.height,
        seconds.count(), frames / seconds.count(), o.out.c_str());
  }
}

}  // namespace lamina::tutorial
