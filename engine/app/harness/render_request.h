// What to render and how: one request for the chapter tutorials and `lamina run` alike, filled
// by the same command-line options, and the one renderer that carries it out.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "language/language.h"
#include "render/backend.h"
#include "render/camera.h"
#include "render/frame.h"
#include "render/overlay.h"
#include "render/style.h"
#include "render/vector_output.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace lamina::tutorial {

// The file formats of frames (docs/slides.md).
enum class FrameFormat { png, svg, pdf };

struct RenderRequest {
  std::filesystem::path out;                             // the folder the frames go to
  render::FrameSize size{1280, 720};                     // --size WxH, in pixels
  render::Overlays overlays;                             // --overlay LIST
  render::Backend backend = render::default_backend();   // --backend
  FrameFormat format = FrameFormat::png;                 // --format png|svg|pdf
  bool pdf_pages = false;                                // --pdf-pages: one PDF of every frame
  render::Background background{};                       // --background paper|transparent|#rrggbb
  std::optional<std::filesystem::path> video{};          // --video FILE: .mp4, .webm or .gif
  int fps = 30;                                          // --fps N of the video
  bool write_frames = true;                              // false: the video alone, no frame files
  bool video_per_scene = false;                          // FILE's stem + "_<scene>" (tutorials)
  bool check_layout = false;                             // --check-layout: record every overlap
  std::optional<Language> language{};                    // --lang en|ko, set_language'd as read
};

// "paper", "transparent" or "#rrggbb"; throws std::invalid_argument for anything else.
render::Background parse_background(const std::string& text);

// Adds --size, --overlay, --backend, --format, --pdf-pages, --background, --video, --fps and
// --lang (which also sets the process's language at once: language.h) to a command line,
// parsed straight into `request`, whose values are the defaults --help shows. A bad value is one
// line naming the option. Returns the options (so that a caller can make them need another, as
// lamina's need --frames or --viewer).
std::vector<CLI::Option*> add_render_options(CLI::App& app, RenderRequest& request);

// Adds --viewer DIR (described by `help`) and --viewer-steps A:B (parse_step_window, viewer.h),
// parsed straight into `viewer` and `steps`; returns the --viewer option.
CLI::Option* add_viewer_options(CLI::App& app, std::optional<std::filesystem::path>& viewer,
                                std::optional<std::array<long, 2>>& steps, const std::string& help);

// "1280x720" → {1280, 720}; throws std::invalid_argument for anything else or a size outside
// 16..8192 pixels.
render::FrameSize parse_frame_size(const std::string& text);

// Fills the next frame and sets the step it shows (its status line reads t = step Δt); false
// once there are no more frames.
using NextFrame = std::function<bool(render::Frame& frame, long& step)>;

// Renders frames into request.out: an OpenGL context on this thread, PNG encoders on others,
// every file complete or absent (engine/output).
class FrameRenderer {
 public:
  // Creates the output folder and opens the context. Throws OutputError or GlContextError.
  explicit FrameRenderer(const RenderRequest& request);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Renders `<name>_0000.png`, `<name>_0001.png`, ... of the world region `view` (fitted once for
  // all of them) until `next` returns false; returns how many. An exception from `next` leaves
  // the frames before it queued.
  int render(const std::string& name, const render::Rect& view, double dt, const NextFrame& next);
  // Waits until every queued frame is written; throws OutputError for the first failure.
  void finish();
  // The camera render() fits to the world region `view`, for the frames' size and overlays.
  render::Camera camera(const render::Rect& view) const;
  // Where the legend of a run's frames goes (docs/slides.md): the first of the corners top right,
  // top left, bottom right and bottom left whose legend box meets no body's, panel's or label's
  // box (as painted) in any of the `count` frames `frame_at` gives; when every corner meets one, the view grows
  // upward by the legend's height, up to 4 times, for top right to be free. Returns the corner
  // and the view to render with.
  struct LegendPlace {
    render::Corner corner = render::Corner::top_right;
    render::Rect view;
  };
  LegendPlace place_legend(std::size_t count, const std::function<const render::Frame&(std::size_t)>& frame_at,
                           render::Rect view);
  // With request.check_layout, each frame rendered whose legend, panels or labels cover a body
  // or each other: "<name>_0012: legend 3 and body 0 overlap" (render::layout_overlaps); that
  // draws a character no font has ("<name>_0012: 2 characters no font has"); or, in a language
  // other than English, that draws English (english_words: "<name>_0012: English "step" in …").
  const std::vector<std::string>& layout_problems() const { return layout_problems_; }
  // The layout boxes (render/draw_list.h) of `frame` as render() would draw it in `view`.
  std::vector<render::LayoutBox> layout(const render::Frame& frame, const render::Rect& view);
  // The video of the scene `name` (request.video, or with video_per_scene its stem + "_name").
  std::filesystem::path video_path(const std::string& name) const;

 private:
  struct Pipeline;
  RenderRequest request_;
  std::unique_ptr<Pipeline> pipeline_;
  std::vector<std::string> layout_problems_;
};

}  // namespace lamina::tutorial
