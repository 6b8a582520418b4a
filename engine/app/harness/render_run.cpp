// Rendering: the GL thread steps the scene and draws; encoder threads write the PNGs.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <thread>

#include "app/harness/render_request.h"
#include "app/harness/runs.h"
#include "app/harness/video.h"
#include "app/harness/viewer.h"
#include "language/language.h"
#include "output/output_file.h"
#include "render/frame_writer.h"
#include "render/paint.h"
#include "render/renderer.h"

namespace lamina::tutorial {
namespace {

constexpr std::size_t queued_frames = 4;  // images waiting for an encoder, at most
constexpr int smallest_side = 16;
constexpr int largest_side = 8192;

int encoder_threads() {
  return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 4u));
}

std::string frame_name(const std::string& scene, int index, const char* extension = "png") {
  char name[32];
  std::snprintf(name, sizeof name, "_%04d.%s", index, extension);
  return scene + name;
}

// "t = 0.500 s · step 30 · Δt = 1/60 s", in the current language
std::string status_line(long step, double dt) {
  char time[32], interval[32];
  std::snprintf(time, sizeof time, "%.3f", step * dt);
  const double rate = 1.0 / dt;
  if (std::abs(rate - std::round(rate)) < 1e-9) {
    std::snprintf(interval, sizeof interval, "1/%.0f", rate);
  } else {
    std::snprintf(interval, sizeof interval, "%.4g", dt);
  }
  return fill(tr("t = {0} s · step {1} · Δt = {2} s"), {time, std::to_string(step), interval});
}

// A CLI11 check that runs `parse` and turns its exception into CLI11's message.
template <typename Parse>
CLI::Validator checked_by(Parse parse, const std::string& description) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      description);
}

}  // namespace

render::FrameSize parse_frame_size(const std::string& text) {
  const char* end = text.data() + text.size();
  render::FrameSize size{0, 0};
  const auto width = std::from_chars(text.data(), end, size.width);
  const bool has_x = width.ec == std::errc() && width.ptr != end && *width.ptr == 'x';
  const auto height = has_x ? std::from_chars(width.ptr + 1, end, size.height) : width;
  if (!has_x || height.ec != std::errc() || height.ptr != end) {
    throw std::invalid_argument("expected WxH such as 1280x720, got '" + text + "'");
  }
  if (std::min(size.width, size.height) < smallest_side ||
      std::max(size.width, size.height) > largest_side) {
    throw std::invalid_argument("each side must be 16..8192 pixels, got '" + text + "'");
  }
  return size;
}

std::vector<CLI::Option*> add_render_options(CLI::App& app, RenderRequest& request) {
  std::vector<std::string> backends;
  for (const auto& built : render::built_backends()) backends.push_back(built.first);
  CLI::Option* size = app.add_option_function<std::string>(
      "--size", [&request](const std::string& text) { request.size = parse_frame_size(text); },
      "frame size in pixels, each side 16..8192");
  size->type_name("WxH")
      ->default_str(std::to_string(request.size.width) + "x" + std::to_string(request.size.height))
      ->check(checked_by(parse_frame_size, "WxH"));
  CLI::Option* overlays = app.add_option_function<std::string>(
      "--overlay",
      [&request](const std::string& text) { request.overlays = render::Overlays::parse(text); },
      "layers to show: contacts, normals, forces, velocities, centres, axes (comma-separated), "
      "all or none");
  overlays->type_name("LIST")
      ->default_str(request.overlays.to_string())
      ->check(checked_by(render::Overlays::parse, "LIST"));
  CLI::Option* backend = app.add_option_function<std::string>(
      "--backend",
      [&request](const std::string& name) { request.backend = render::built_backends().at(name); },
      "OpenGL backend (both draw the same pixels)");
  backend->type_name("NAME")
      ->default_str(render::backend_name(request.backend))
      ->check(CLI::IsMember(backends));
  const std::map<std::string, FrameFormat> formats{
      {"png", FrameFormat::png}, {"svg", FrameFormat::svg}, {"pdf", FrameFormat::pdf}};
  CLI::Option* format = app.add_option_function<std::string>(
      "--format", [&request, formats](const std::string& name) { request.format = formats.at(name); },
      "png, or svg and pdf, vector frames whose text stays text (docs/slides.md)");
  format->type_name("FORMAT")->default_str("png")->check(CLI::IsMember({"png", "svg", "pdf"}));
  CLI::Option* pages = app.add_flag("--pdf-pages", request.pdf_pages,
                                    "with --format pdf: one PDF of all the frames, a page each, "
                                    "instead of a file per frame");
  CLI::Option* background = app.add_option_function<std::string>(
      "--background",
      [&request](const std::string& text) { request.background = parse_background(text); },
      "behind the drawing: paper, transparent (PNG with alpha, SVG, PDF) or a colour #rrggbb");
  background->type_name("COLOUR")->default_str("paper")->check(checked_by(parse_background, "COLOUR"));
  CLI::Option* video = app.add_option_function<std::string>(
                             "--video", [&request](const std::string& file) { request.video = file; },
                             "also encode the frames as a video: FILE.mp4 (H.264), .webm (VP9) or "
                             ".gif (by Debian's ffmpeg; docs/slides.md)")
                           ->type_name("FILE");
  CLI::Option* fps = app.add_option("--fps", request.fps, "frames per second of the video")
                         ->type_name("N")
                         ->capture_default_str()
                         ->check(CLI::Range(1, 240))
                         ->needs(video);
  // The language is the process's (language.h), set as the options are read, before any output.
  CLI::Option* lang = app.add_option_function<std::string>(
      "--lang",
      [&request](const std::string& code) {
        request.language = language_named(code);
        set_language(*request.language);
      },
      "the language of captions, legends, panels, plots and explanations: en or ko (Korean, the "
      "text's language; docs/slides.md)");
  lang->type_name("LANG")->default_str("en")->check(CLI::IsMember({"en", "ko"}));
  return {size, overlays, backend, format, pages, background, video, fps, lang};
}

render::Background parse_background(const std::string& text) {
  render::Background background;
  if (text == "paper") return background;
  if (text == "transparent") {
    background.transparent = true;
    return background;
  }
  unsigned int r = 0, g = 0, b = 0;
  char end = 0;
  if (text.size() != 7 || std::sscanf(text.c_str(), "#%2x%2x%2x%c", &r, &g, &b, &end) != 3) {
    throw std::invalid_argument("expected paper, transparent or #rrggbb, got '" + text + "'");
  }
  background.colour = {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b)};
  return background;
}

CLI::Option* add_viewer_options(CLI::App& app, std::optional<std::filesystem::path>& viewer,
                                std::optional<std::array<long, 2>>& steps, const std::string& help) {
  CLI::Option* folder = app.add_option_function<std::string>(
                                "--viewer", [&viewer](const std::string& text) { viewer = text; }, help)
                            ->type_name("DIR");
  app.add_option_function<std::string>(
         "--viewer-steps", [&steps](const std::string& text) { steps = parse_step_window(text); },
         "the steps whose phases, rows and sweeps the viewer keeps, A:B (default: from step 0 "
         "while they fit in 16 MB)")
      ->type_name("A:B")
      ->check(checked_by(parse_step_window, "A:B"))
      ->needs(folder);
  return folder;
}

struct FrameRenderer::Pipeline {
  std::unique_ptr<render::GlContext> context;
  render::Renderer renderer;
  render::FrameWriter writer;

  explicit Pipeline(const RenderRequest& r)
      : context(render::open_context(r.backend)),
        renderer(*context, r.size),
        writer(encoder_threads(), queued_frames) {}
};

FrameRenderer::FrameRenderer(const RenderRequest& request) : request_(request) {
  if (request_.video && request_.background.transparent) {
    throw OutputError("--background transparent: a video is opaque; leave --video out or the background in");
  }
  if (request_.pdf_pages && request_.format != FrameFormat::pdf) {
    throw OutputError("--pdf-pages needs --format pdf");
  }
  if (request_.video) check_video(*request_.video, request_.size, request_.fps);
  if (request_.write_frames) prepare_output_folder(request_.out);
  pipeline_ = std::make_unique<Pipeline>(request_);
  pipeline_->renderer.set_background(request_.background);
}

FrameRenderer::LegendPlace FrameRenderer::place_legend(
    std::size_t count, const std::function<const render::Frame&(std::size_t)>& frame_at, render::Rect view) {
  using render::Corner;
  using Kind = render::LayoutBox::Kind;
  const render::Rect area = render::Style::for_size(request_.size)
                                .drawing_area(request_.size, request_.overlays.has(render::Overlay::axes));
  for (int grown = 0;; ++grown) {
    const render::Camera camera = this->camera(view);
    // every corner free until a frame's legend there meets one of its bodies
    std::array<bool, 4> free{true, true, true, true};
    double legend_height = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      const render::DrawList list = pipeline_->renderer.paint(frame_at(k), camera, request_.overlays);
      Vec2 size = Vec2::Zero();
      for (const render::LayoutBox& b : list.layout()) {
        if (b.kind == Kind::legend) size = b.rect.max - b.rect.min;
      }
      if (size.isZero()) continue;  // no legend in this frame
      legend_height = std::max(legend_height, size.y());
      for (const Corner corner : {Corner::top_right, Corner::top_left, Corner::bottom_right, Corner::bottom_left}) {
        const Vec2 at = render::corner_position(area, corner, size);
        for (const render::LayoutBox& b : list.layout()) {
          const bool meets = b.kind != Kind::legend && at.x() < b.rect.max.x() && b.rect.min.x() < at.x() + size.x() &&
                             at.y() < b.rect.max.y() && b.rect.min.y() < at.y() + size.y();
          if (meets) free[static_cast<std::size_t>(corner)] = false;
        }
      }
    }
    for (const Corner corner : {Corner::top_right, Corner::top_left, Corner::bottom_right, Corner::bottom_left}) {
      if (free[static_cast<std::size_t>(corner)]) return {corner, view};
    }
    if (grown == 4) return {Corner::top_right, view};  // as free as it gets
    // room above the scene for the legend: its height in metres, at the current scale
    view.max.y() += (legend_height + 0.5 * area.size().y() / 10.0) / camera.pixels_per_metre();
  }
}

std::vector<render::LayoutBox> FrameRenderer::layout(const render::Frame& frame, const render::Rect& view) {
  return pipeline_->renderer.paint(frame, camera(view), request_.overlays).layout();
}

std::filesystem::path FrameRenderer::video_path(const std::string& name) const {
  if (!request_.video_per_scene) return *request_.video;
  std::filesystem::path path = *request_.video;
  return path.replace_filename(path.stem().string() + "_" + name + path.extension().string());
}

FrameRenderer::~FrameRenderer() = default;

int FrameRenderer::render(const std::string& name, const render::Rect& view, double dt,
                          const NextFrame& next) {
  const render::Camera camera = this->camera(view);
  int count = 0;
  render::Frame frame;
  long step = 0;
  // --pdf-pages: every frame a page of <name>.pdf, written whole once the last is drawn
  std::optional<render::PdfDocument> pages;
  if (request_.pdf_pages) pages.emplace(request_.size);
  // --video: the frames also go, as pixels, to ffmpeg
  std::optional<VideoEncoder> video;
  if (request_.video) video.emplace(video_path(name), request_.size, request_.fps);
  while (next(frame = render::Frame(), step)) {
    // t and the step, unless the scene's frame says where it is itself (an algorithm's iteration)
    if (frame.status.empty()) frame.status = status_line(step, dt);
    render::Renderer& renderer = pipeline_->renderer;
    if (request_.check_layout) {  // paint and check; draw and write nothing
      char index[16];
      std::snprintf(index, sizeof index, "_%04d", count);
      const long missing_before = renderer.missing_glyphs();
      const render::DrawList list = renderer.paint(frame, camera, request_.overlays);
      for (const std::string& overlap : render::layout_overlaps(list.layout())) {
        layout_problems_.push_back(name + index + ": " + overlap);
      }
      if (renderer.missing_glyphs() > missing_before) {
        layout_problems_.push_back(name + index + ": " +
                                   std::to_string(renderer.missing_glyphs() - missing_before) +
                                   " characters no font has");
      }
      if (current_language() != Language::en) {  // a translated frame: no English left
        for (const render::DrawCommand& command : list.commands()) {
          for (const std::string& word : english_words(command.text)) {
            layout_problems_.push_back(name + index + ": English \"" + word + "\" in \"" +
                                       command.text + "\"");
          }
        }
      }
      ++count;
      continue;
    }
    if (video) {
      render::Image image = renderer.render(frame, camera, request_.overlays);
      video->add(image);
      if (!request_.write_frames) {
        ++count;
        continue;
      }
      if (request_.format == FrameFormat::png) {
        pipeline_->writer.submit(request_.out / frame_name(name, count++), std::move(image));
        continue;
      }
    }
    if (!request_.write_frames) continue;
    switch (request_.format) {
      case FrameFormat::png:
        pipeline_->writer.submit(request_.out / frame_name(name, count++),
                                 renderer.render(frame, camera, request_.overlays));
        break;
      case FrameFormat::svg:
        write_file_atomically(request_.out / frame_name(name, count++, "svg"),
                              render::svg_document(renderer.paint(frame, camera, request_.overlays),
                                                   request_.size, request_.background));
        break;
      case FrameFormat::pdf: {
        const render::DrawList list = renderer.paint(frame, camera, request_.overlays);
        if (pages) {
          pages->add_page(list, request_.background);
          ++count;
          break;
        }
        render::PdfDocument one(request_.size);
        one.add_page(list, request_.background);
        write_file_atomically(request_.out / frame_name(name, count++, "pdf"), one.finish());
        break;
      }
    }
  }
  if (pages && count > 0) write_file_atomically(request_.out / (name + ".pdf"), pages->finish());
  if (video) video->finish();
  return count;
}

void FrameRenderer::finish() { pipeline_->writer.finish(); }

render::Camera FrameRenderer::camera(const render::Rect& view) const {
  const render::Rect area = render::Style::for_size(request_.size)
                                .drawing_area(request_.size, request_.overlays.has(render::Overlay::axes));
  return render::Camera::fit(view, area);
}

void render_scenes(const TutorialInfo& info, const Options& o,
                   const std::vector<SceneFactory>& scenes) {
  RenderRequest request = o.render;
  request.video_per_scene = scenes.size() > 1;  // --video FILE: FILE's stem + "_<scene>" each
  FrameRenderer renderer(request);
  for (const SceneFactory& make : scenes) {
    const auto start = std::chrono::steady_clock::now();
    const auto scene = make(o);
    const SceneInfo s = scene->info();
    const int frames = o.frames.value_or(s.frames), every = o.every.value_or(s.every);
    int drawn = 0;
    // Frame f shows step f × every: the state at its t, with what that step solved.
    renderer.render(s.name, s.view, s.time_step, [&](render::Frame& frame, long& step) {
      if (drawn == frames) return false;
      for (int k = 0; drawn > 0 && k < every; ++k) scene->step();
      scene->draw(frame);
      step = static_cast<long>(drawn++) * every;
      return true;
    });
    renderer.finish();
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    scene->write_data(o.render.out);
    std::printf(
        "%s: %d frames of %s, %dx%d, in %.2f s (%.1f frames/s: physics, render, "
        "encode, write) -> %s\n",
        info.name.c_str(), frames, s.name.c_str(), o.render.size.width, o.render.size.height,
        seconds.count(), frames / seconds.count(), o.render.out.c_str());
  }
  if (!renderer.layout_problems().empty()) {
    std::string list;
    for (const std::string& p : renderer.layout_problems()) list += "\n  " + p;
    throw std::runtime_error("--check-layout: " + std::to_string(renderer.layout_problems().size()) +
                             " overlaps:" + list);
  }
}

}  // namespace lamina::tutorial
