#include "harness/options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace lamina::tutorial {
namespace {

constexpr int smallest_side = 16;
constexpr int largest_side = 8192;

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

ParsedOptions parse_options(int argc, char** argv, const TutorialInfo& info) {
  CLI::App app(info.summary, info.name);
  Options o;
  std::string out = "images/" + info.chapter;
  std::string size = "1280x720", overlays = info.default_overlays.to_string(), format = "text";
  std::string backend = render::backend_name(render::default_backend());
  std::vector<std::string> backends;
  for (const auto& built : render::built_backends()) backends.push_back(built.first);
  int frames = 0, every = 0;
  long explain = 0;
  app.add_option("--out", out, "folder for the frames, CSV data and plots")->capture_default_str();
  auto* frames_option =
      app.add_option("--frames", frames, "frames per scene")->check(CLI::PositiveNumber);
  auto* every_option =
      app.add_option("--every", every, "time steps between frames")->check(CLI::PositiveNumber);
  app.add_option("--size", size, "frame size WxH in pixels")
      ->capture_default_str()
      ->check(checked_by(parse_frame_size, "WxH"));
  app.add_option("--overlay", overlays,
                 "layers to show: contacts,normals,forces,velocities,"
                 "centres,axes, or all, or none")
      ->capture_default_str()
      ->check(checked_by(render::Overlays::parse, "LIST"));
  auto* explain_option = app.add_option("--explain", explain,
                                        "print what the engine computed at "
                                        "this step, with equation numbers; renders nothing")
                             ->check(CLI::NonNegativeNumber);
  app.add_option("--explain-format", format, "text or json")
      ->capture_default_str()
      ->check(CLI::IsMember({"text", "json"}));
  app.add_flag("--step-through", o.step_through,
               "print every step in turn (Enter for the next, "
               "q to stop); renders nothing")
      ->excludes(explain_option);
  app.add_option("--backend", backend, "OpenGL backend (both draw the same pixels)")
      ->capture_default_str()
      ->check(CLI::IsMember(backends));
  if (info.has_cache) app.add_flag("--no-cache", o.no_cache, "solve without the contact cache");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return {std::nullopt, app.exit(e)};
  }
  o.out = out;
  if (*frames_option) o.frames = frames;
  if (*every_option) o.every = every;
  if (*explain_option) o.explain_step = explain;
  o.size = parse_frame_size(size);
  o.overlays = render::Overlays::parse(overlays);
  o.json = format == "json";
  o.backend = render::built_backends().at(backend);
  return {o, 0};
}

}  // namespace lamina::tutorial
