#include "app/harness/viewer.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "app/harness/format.h"
#include "app/harness/viewer_page.h"
#include "language/language.h"
#include "output/output_file.h"

namespace lamina::tutorial {
namespace {

// ±∞ (a bound) as null: JSON has no infinity.
Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json body_json(const ViewerBody& b) {
  return Json::array({b.x, b.y, b.theta, b.vx, b.vy, b.omega, b.energy, b.fixed ? 1 : 0});
}

Json bodies_json(const std::vector<ViewerBody>& bodies) {
  Json list = Json::array();
  for (const ViewerBody& b : bodies) list.push_back(body_json(b));
  return list;
}

// What every step keeps: the bodies, the contacts and the joints (small).
Json step_json(long k, double t, const ViewerStep& s) {
  Json contacts = Json::array();
  for (const ViewerContact& c : s.contacts) {
    contacts.push_back({{"bodies", c.bodies},
                        {"p", {c.x, c.y}},
                        {"n", {c.nx, c.ny}},
                        {"C", c.separation},
                        {"ln", c.lambda_normal},
                        {"lt", c.lambda_tangent},
                        {"origin", c.origin},
                        {"row", c.row}});
  }
  Json joints = Json::array();
  for (const ViewerJoint& j : s.joints) {
    joints.push_back({{"title", j.title},
                      {"a", {j.x1, j.y1}},
                      {"b", {j.x2, j.y2}},
                      {"rows", {j.first_row, j.row_count}}});
  }
  return {{"k", k},
          {"t", t},
          {"at_t", bodies_json(s.at_t)},
          {"contacts", contacts},
          {"joints", joints}};
}

// What a detailed step adds: its phases, rows and sweeps.
Json detail_json(const ViewerStep& s) {
  Json sections = to_json(StepContext{}, s.phases)["sections"];
  Json rows = Json::array();
  for (const ViewerRow& r : s.rows) {
    rows.push_back({{"kind", r.kind},
                    {"title", r.title},
                    {"bodies", r.bodies},
                    {"J", r.J},
                    {"d", r.d},
                    {"eta", r.eta},
                    {"lo", finite_or_null(r.lower)},
                    {"hi", finite_or_null(r.upper)},
                    {"lexp", r.lambda_exp},
                    {"l", r.lambda},
                    {"W", r.slack},
                    {"sweeps", r.sweeps},
                    {"contact", r.contact},
                    {"joint", r.joint}});
  }
  return {{"method", s.method}, {"phases", sections}, {"rows", rows}, {"residuals", s.residuals}};
}

// "<run>-<scene>": the frames' file prefix.
std::string frame_prefix(std::size_t run, const std::string& scene) {
  return file_prefix(std::to_string(run) + "-" + scene);
}

}  // namespace

std::array<long, 2> parse_step_window(const std::string& text) {
  const char* end = text.data() + text.size();
  std::array<long, 2> window{-1, -1};
  const auto first = std::from_chars(text.data(), end, window[0]);
  const bool colon = first.ec == std::errc() && first.ptr != end && *first.ptr == ':';
  const auto last = colon ? std::from_chars(first.ptr + 1, end, window[1]) : first;
  if (!colon || last.ec != std::errc() || last.ptr != end || window[0] < 0 || window[1] < window[0]) {
    throw std::invalid_argument("expected A:B with 0 <= A <= B, such as 40:80, got '" + text + "'");
  }
  return window;
}

ViewerRun::ViewerRun(std::string program, std::string scene, double dt, const ViewerLimits& limits)
    : program_(std::move(program)), scene_(std::move(scene)), dt_(dt), limits_(limits) {}

void ViewerRun::add(const ViewerStep& step, render::Frame frame) {
  const long k = steps();
  if (steps_json_.empty()) body_names_ = step.body_names;
  final_json_ = bodies_json(step.after).dump();  // step k + 1's bodies at t are step k's after
  steps_json_.push_back(step_json(k, k * dt_, step).dump());
  frames_.push_back(std::move(frame));
  const bool in_window = !limits_.window || ((*limits_.window)[0] <= k && k <= (*limits_.window)[1]);
  if (!in_window || detail_full_) return;
  std::string detail = detail_json(step).dump();
  // the window is contiguous: once a step does not fit, no later step is kept
  if (detail_bytes_ + detail.size() > limits_.detail_bytes) {
    detail_full_ = true;
    return;
  }
  if (first_detail_ < 0) first_detail_ = k;
  detail_bytes_ += detail.size();
  details_json_.push_back(std::move(detail));
}

std::optional<std::array<long, 2>> ViewerRun::detailed() const {
  if (first_detail_ < 0) return std::nullopt;
  return std::array<long, 2>{first_detail_, first_detail_ + static_cast<long>(details_json_.size()) - 1};
}

ViewerPage::ViewerPage(const RenderRequest& request) : request_(request) {
  prepare_output_folder(request_.out);
}

std::size_t ViewerPage::write(const std::vector<ViewerRun>& runs, const StopCheck& stop) {
  try {
    return write_page(runs, stop);
  } catch (...) {
    // no page: the frames this call wrote go too (data.js and index.html are written whole or
    // not at all, last)
    std::error_code ignored;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      for (std::size_t k = 0; k < runs[i].frames_.size(); ++k) {
        std::filesystem::remove(frame_path(i, runs[i], k), ignored);
      }
    }
    throw;
  }
}

std::filesystem::path ViewerPage::frame_path(std::size_t run, const ViewerRun& r, std::size_t k) const {
  char index[24];
  std::snprintf(index, sizeof index, "_%04zu.png", k);
  return request_.out / "frames" / (frame_prefix(run, r.scene_) + index);
}

std::size_t ViewerPage::write_page(const std::vector<ViewerRun>& runs, const StopCheck& stop) {
  const std::filesystem::path frames = request_.out / "frames";
  FrameRenderer renderer([&] {
    RenderRequest r = request_;
    r.out = frames;
    r.format = FrameFormat::png;  // the page shows PNGs, whatever --format the frames have
    r.pdf_pages = false;
    r.background.transparent = false;
    return r;
  }());
  // the page as one script: data.js sets LAMINA_VIEWER before index.html's own script reads it
  std::string data = "window.LAMINA_VIEWER = {\"runs\": [";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const ViewerRun& run = runs[i];
    const std::string prefix = frame_prefix(i, run.scene_);
    std::size_t next = 0;
    const FrameRenderer::LegendPlace place = renderer.place_legend(
        run.frames_.size(), [&](std::size_t k) -> const render::Frame& { return run.frames_[k]; }, run.view_);
    renderer.render(prefix, place.view, run.dt_, [&](render::Frame& frame, long& step) {
      if (next == run.frames_.size()) return false;
      if (stop) stop();
      frame = run.frames_[next];
      frame.legend_corner = place.corner;
      step = static_cast<long>(next++);
      return true;
    });
    const render::Camera camera = renderer.camera(place.view);
    const Vec2 origin = camera.to_pixels(Vec2::Zero());
    const std::optional<std::array<long, 2>> detailed = run.detailed();
    Json head = {{"program", run.program_},
                 {"scene", run.scene_},
                 {"dt", run.dt_},
                 {"steps", run.steps()},
                 {"bodies", run.body_names_},
                 {"frames", {{"prefix", "frames/" + prefix + "_"},
                             {"width", request_.size.width},
                             {"height", request_.size.height},
                             {"origin", {origin.x(), origin.y()}},
                             {"scale", camera.pixels_per_metre()}}},
                 {"detail", detailed ? Json(*detailed) : Json(nullptr)}};
    std::string text = head.dump();
    text.pop_back();  // the closing brace: the steps follow
    text += ", \"step\": [";
    for (std::size_t k = 0; k < run.steps_json_.size(); ++k) text += (k ? ",\n" : "\n") + run.steps_json_[k];
    text += "], \"final\": " + run.final_json_ + ", \"detail_of\": [";
    for (std::size_t k = 0; k < run.details_json_.size(); ++k) text += (k ? ",\n" : "\n") + run.details_json_[k];
    text += "]}";
    data += (i ? ",\n" : "\n") + text;
  }
  // the page's own words in the run's language: the translation of each t("…") it has
  const std::string page = viewer_page_html();
  Json messages = Json::object();
  for (const auto& [english, translated] : translations()) {
    if (page.find("t(" + Json(english).dump()) != std::string::npos) messages[english] = translated;
  }
  // the statements of the text's equations (the-text.md), each in the run's language
  Json equations = Json::parse(equation_table_json());
  for (auto& [number, statement] : equations.items()) statement = tr(statement.get<std::string>().c_str());
  data += "],\n\"equations\": " + equations.dump() + ",\n\"lang\": \"" +
          language_code(current_language()) + "\",\n\"messages\": " + messages.dump() + "};\n";
  renderer.finish();
  write_file_atomically(request_.out / "data.js", data);
  write_file_atomically(request_.out / "index.html", page);  // last: the page is whole
  return data.size() + page.size();
}

}  // namespace lamina::tutorial
