#include "ch3/constrained_system.h"

#include <algorithm>

#include "app/views/constraints/mlcp_explanation.h"
#include "app/views/motion/body_view.h"
#include "ch3/text_pgs_explanation.h"
#include "language/language.h"

namespace lamina::ch3 {

void System::step(std::vector<double> errors) {
  C = std::move(errors);
  at_t = bodies;
  constrained_step(bodies, constraints, settings, warm_start, &report);
  ++step_index;
}

double System::last_residual() const {
  return report.solution.residuals.empty() ? 0.0 : report.solution.residuals.back();
}

tutorial::Explanation explain_system(const System& s, const std::string& title,
                                     const std::vector<std::string>& row_names) {
  tutorial::Explanation e;
  const std::vector<std::string> bodies = view::numbered_bodies(s.bodies.size());
  for (std::size_t b = 0; b < s.at_t.size(); ++b) {
    e.push_back(view::body_section(fill(tr("{0}: {1} at t"), {title, bodies[b]}), s.at_t[b],
                                   {"", "", "3-5", "3-5"}));
  }
  for (int i = 0; i < s.report.mlcp.row_count(); ++i) {
    tutorial::Section row = view::row_section(
        s.report, i, fill(tr("{0}: row {1}: {2}"), {title, std::to_string(i), row_names.at(i)}),
        bodies);
    // C goes just before ζ = −β C / Δt, which it gives (eq. 3-13, 3-14)
    const auto zeta = std::find_if(row.quantities.begin(), row.quantities.end(),
                                   [](const tutorial::Quantity& q) { return q.symbol == "ζ"; });
    row.quantities.insert(zeta, {"C", "3-13", tr("position error ε at t"), s.C.at(i), "m"});
    e.push_back(row);
  }
  e.push_back(
      view::sweeps_section(s.report, fill(tr("{0}: projected Gauss-Seidel (eq. 3-24)"), {title})));
  e.push_back(text_pgs_section(
      s, fill(tr("{0}: the same step by the text's Projected Gauss-Seidel"), {title})));
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    tutorial::Section after = view::body_section(fill(tr("{0}: {1} at t + Δt"), {title, bodies[b]}),
                                                 s.bodies[b], {"2-5", "2-6", "2-3", "2-4"});
    after.quantities.insert(after.quantities.begin(), view::constraint_force(s.report, static_cast<int>(b)));
    e.push_back(after);
  }
  if (auto dense =
          view::dense_section(s.report, s.at_t, fill(tr("{0}: the dense system"), {title})))
    e.push_back(*dense);
  return e;
}

void record_system(const System& s, const std::vector<std::string>& row_names,
                   tutorial::ViewerStep& step) {
  step.body_names = view::numbered_bodies(s.bodies.size());
  for (const RigidBody& b : s.at_t) step.at_t.push_back(view::viewer_body(b, gravity));
  for (const RigidBody& b : s.bodies) step.after.push_back(view::viewer_body(b, gravity));
  step.method = "PGS (constrained_step)";
  view::add_viewer_rows(s.report, row_names, step);
  for (tutorial::ViewerRow& row : step.rows) row.kind = "joint";
}

render::Body mount(const Vec3& pivot) {
  render::Body m;
  m.centre = planar(pivot) + Vec2(0.0, 0.08);
  m.half_extents = {0.25, 0.08};
  m.fill = tint(render::palette::grey, 0.5);
  m.fixed = true;
  return m;
}

}  // namespace lamina::ch3
