// The step-through viewer (docs/viewer.md): a static page, DIR/index.html, that shows a run step
// by step and, inside a step, sweep by sweep — the frame of the step, its phases in
// World::step's order with the numbers and equation numbers of its explanation, the rows of its
// MLCP with λ after every sweep, and the bodies at t and t + Δt.
//
// What a step recorded is plain data here (ViewerStep), filled by the views of the stage that
// computed it (views_constraints: rows; views_contact: a World's step); the harness writes it
// as JSON beside the page (data.js, a script, so that the page opens from the file system) and
// renders one PNG per step with the frames' renderer.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/harness/explanation.h"
#include "app/harness/render_request.h"
#include "render/frame.h"

namespace lamina::tutorial {

// A body's planar state as the page shows it (x–y plane, θ about z).
struct ViewerBody {
  double x = 0.0, y = 0.0, theta = 0.0;  // centre in m, angle in rad
  double vx = 0.0, vy = 0.0, omega = 0.0;  // m/s, rad/s
  double energy = 0.0;  // ½ m v·v + ½ ω·I ω − m g·x, in J (0 for a static body)
  bool fixed = false;   // static (the ground)
};

// One row of the step's velocity MLCP (eq. 3-16, 3-24), as assembled and as solved.
struct ViewerRow {
  std::string kind;   // "contact", "friction" or "joint"
  std::string title;  // e.g. "contact row of contact 0 (ground, box) (eq. 4-3)"
  std::array<int, 2> bodies{-1, -1};  // Jmap: body indices, −1 for none (a one-body row)
  std::array<std::array<double, 3>, 2> J{};  // the planar J blocks [J_x, J_y, J_θ] of each body
  double d = 0.0, eta = 0.0;          // d = J B (its diagonal), η (eq. 3-16)
  double lower = 0.0, upper = 0.0;    // the bounds as solved (eq. 3-24, 3-26; ±∞ as ±1e300)
  double lambda_exp = 0.0, lambda = 0.0, slack = 0.0;  // warm start, answer, W (eq. 3-23)
  std::vector<double> sweeps;         // λ after each sweep
  int contact = -1;                   // the contact it belongs to (index into contacts), or −1
  int joint = -1;                     // the joint it belongs to, or −1
};

struct ViewerContact {
  std::array<int, 2> bodies{-1, -1};
  double x = 0.0, y = 0.0, nx = 0.0, ny = 1.0;  // point and normal (Fig 4-2)
  double separation = 0.0;                       // C (eq. 4-1), m
  double lambda_normal = 0.0, lambda_tangent = 0.0;
  std::string origin;  // "new", "re-found" or "kept" (Fig 4-2..4-5)
  int row = -1;        // its contact row
};

struct ViewerJoint {
  std::string title;
  double x1 = 0.0, y1 = 0.0, x2 = 0.0, y2 = 0.0;  // the two ends drawn, m
  int first_row = 0, row_count = 0;
};

// What one step recorded. Step k goes from t = k Δt to t + Δt.
struct ViewerStep {
  Explanation phases;  // the step's explanation, each section tagged with its phase
  std::vector<std::string> body_names;
  std::vector<ViewerBody> at_t, after;  // the bodies at t and at t + Δt
  std::vector<ViewerRow> rows;
  std::vector<double> residuals;  // after each sweep
  std::string method;             // how λ was solved, e.g. "PGS, 10 sweeps"
  std::vector<ViewerContact> contacts;
  std::vector<ViewerJoint> joints;
};

// How much of a run keeps its rows and sweeps.
struct ViewerLimits {
  std::optional<std::array<long, 2>> window;  // --viewer-steps A:B (inclusive)
  std::size_t detail_bytes = 16u << 20;       // rows and sweeps, at most (the page stays < 20 MB)
};

// "A:B" → {A, B}; throws std::invalid_argument unless 0 ≤ A ≤ B.
std::array<long, 2> parse_step_window(const std::string& text);

// One run of the page (a tutorial has one per scene): its steps' data and frames, kept as
// they come, written by ViewerPage.
class ViewerRun {
 public:
  ViewerRun(std::string program, std::string scene, double dt, const ViewerLimits& limits);

  // Step k = steps() with its frame (the state at t, as the PNG frames draw it).
  void add(const ViewerStep& step, render::Frame frame);
  // The world region every frame shows (known up front for a tutorial's scene, fitted to what
  // the bodies swept for `lamina run`).
  void fit(const render::Rect& view) { view_ = view; }
  long steps() const { return static_cast<long>(frames_.size()); }
  const std::string& scene() const { return scene_; }
  // The steps that kept their rows and sweeps, [first, last]; empty when none.
  std::optional<std::array<long, 2>> detailed() const;

 private:
  friend class ViewerPage;
  std::string program_, scene_;
  std::vector<std::string> body_names_;
  double dt_;
  render::Rect view_{{-1.0, -1.0}, {1.0, 1.0}};
  ViewerLimits limits_;
  std::vector<std::string> steps_json_;    // per step: bodies at t, contacts, joints
  std::string final_json_ = "[]";          // the bodies after the last step
  std::vector<std::string> details_json_;  // per detailed step: phases, rows, sweeps
  long first_detail_ = -1;
  std::size_t detail_bytes_ = 0;
  bool detail_full_ = false;
  std::vector<render::Frame> frames_;
};

// The page: DIR/index.html, DIR/data.js and DIR/frames/<run>_NNNN.png. index.html is written
// last, so a folder without it holds no page; a write that fails removes what it wrote.
class ViewerPage {
 public:
  // Makes the folder (OutputError: one line naming it) before any step is taken.
  explicit ViewerPage(const RenderRequest& request);

  // Called before each frame is rendered; throws to stop (Ctrl-C).
  using StopCheck = std::function<void()>;

  // Renders every frame of the runs and writes the page; returns the bytes of data.js and
  // index.html. An exception (from `stop`, or a write that failed) removes the frames this call
  // wrote and leaves no data.js or index.html of its own.
  std::size_t write(const std::vector<ViewerRun>& runs, const StopCheck& stop = {});

 private:
  std::size_t write_page(const std::vector<ViewerRun>& runs, const StopCheck& stop);
  std::filesystem::path frame_path(std::size_t run, const ViewerRun& r, std::size_t k) const;

  RenderRequest request_;
};

}  // namespace lamina::tutorial
