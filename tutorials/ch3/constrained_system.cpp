#include "ch3/constrained_system.h"

#include <cmath>

#include "constraints/dense_system.h"
#include "harness/body_view.h"

namespace lamina::ch3 {
namespace {

using tutorial::Json;

Json json_of(const Eigen::VectorXd& v) {
  Json a = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

Json json_of(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    rows.push_back(json_of(Eigen::VectorXd(m.row(r).transpose())));
  return rows;
}

// JSON has no infinity: an unbounded λ⁻ or λ⁺ is the string "-inf" or "inf".
Json json_of_bound(double bound) {
  if (std::isinf(bound)) return bound < 0 ? "-inf" : "inf";
  return bound;
}

// One section per row: its bodies, J blocks, C (the scene's), ζ, η, d, bounds, λ_exp, λ, W.
void explain_rows(const System& s, const std::vector<std::string>& names,
                  tutorial::Explanation& e) {
  const StepReport& r = s.report;
  for (std::size_t i = 0; i < r.mlcp.rows.size(); ++i) {
    const ConstraintRow& row = r.mlcp.rows[i];
    const auto n = static_cast<Eigen::Index>(i);
    const auto [lo, hi] = row_bounds(row, r.solution.lambda);
    tutorial::Section section{"Row " + std::to_string(i) + ": " + names[i], {}};
    auto& q = section.quantities;
    q.push_back({"Jmap",
                 "",
                 "the row's two bodies (−1: the world), \"Computing Jacobian\"",
                 {row.Jmap[0], row.Jmap[1]},
                 ""});
    q.push_back({"Jsp[0]", "3-7", "J block of body Jmap[0], [v ω]",
                 json_of(Eigen::VectorXd(row.Jsp[0])), ""});
    if (!row.is_one_body()) {
      q.push_back({"Jsp[1]", "3-7", "J block of body Jmap[1], [v ω]",
                   json_of(Eigen::VectorXd(row.Jsp[1])), ""});
    }
    q.push_back({"C", "3-13", "position error ε at the start of the step", s.C[i], "m"});
    q.push_back({"ζ", "3-14, 3-15", "−β C / Δt: asks J V(t+Δt) = ζ", row.zeta, "m/s"});
    q.push_back({"η", "3-16", "ζ/Δt − J (V/Δt + M⁻¹ F_ext)", r.mlcp.eta[n], "m/s²"});
    q.push_back({"d", "3-16", "J_i M⁻¹ J_iᵀ, the diagonal of J B", r.mlcp.d[n], "1/kg"});
    q.push_back({"[λ⁻, λ⁺]",
                 "3-24, 3-25",
                 "bounds of λ (an equality row: unbounded)",
                 {json_of_bound(lo), json_of_bound(hi)},
                 "N"});
    q.push_back({"λ_exp", "", "PGS's starting guess: last step's λ (warm start) or 0",
                 r.lambda_exp[n], "N"});
    q.push_back({"λ", "3-16, 3-24", "the constraint force's size; impulse λ Δt",
                 r.solution.lambda[n], "N"});
    q.push_back({"W", "3-23", "J B λ − η, 0 for a solved equality row", r.W[n], "m/s²"});
    e.push_back(std::move(section));
  }
}

}  // namespace

// The bodies after the step, the solver's sweeps and, when small, the dense matrices.
tutorial::Explanation explain_system(const System& s, const std::string& title,
                                     const std::vector<std::string>& row_names) {
  tutorial::Explanation e;
  tutorial::Section bodies{title + ": bodies after the step", {}};
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const RigidBody& body = s.bodies[b];
    const std::string n = s.bodies.size() > 1 ? " " + std::to_string(b) : "";
    bodies.quantities.push_back({"x" + n, "2-5", "centre of mass", tutorial::json_of(body.x), "m"});
    bodies.quantities.push_back({"v" + n, "2-3", "velocity", tutorial::json_of(body.v), "m/s"});
    bodies.quantities.push_back(
        {"ω" + n, "2-4", "angular velocity", tutorial::json_of(body.angular_velocity), "rad/s"});
    if (s.stepped) {
      const Vec6 f = s.constraint_force(static_cast<int>(b));
      bodies.quantities.push_back({"F_c" + n, "3-11", "Jᵀ λ on this body, [F τ] (N, N·m)",
                                   json_of(Eigen::VectorXd(f)), ""});
    }
  }
  e.push_back(std::move(bodies));
  if (!s.stepped) return e;  // step 0: nothing solved yet
  explain_rows(s, row_names, e);
  const StepReport& r = s.report;
  const std::vector<double>& res = r.solution.residuals;
  e.push_back({title + ": projected Gauss-Seidel",
               {{"sweeps", "", "MAX_ITERATION of the text", r.solution.iterations, ""},
                {"‖W‖ per sweep", "3-23, 3-24", "MLCP residual after each sweep",
                 json_of(Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(
                     res.data(), static_cast<Eigen::Index>(res.size())))),
                 "m/s²"}}});
  const int n = static_cast<int>(s.bodies.size());
  const Eigen::MatrixXd J = dense_jacobian(r.mlcp.rows, n);
  const Eigen::MatrixXd Bt = dense_b_transpose(r.mlcp);
  tutorial::Section dense{title + ": the dense system", {}};
  if (n <= 2) {  // 6n ≤ 12 columns: readable in a terminal
    dense.quantities.push_back({"J", "3-8", "s × 6n Jacobian", json_of(J), ""});
    dense.quantities.push_back(
        {"M⁻¹", "3-12", "diag(m⁻¹E, I⁻¹)", json_of(dense_inverse_mass(s.bodies)), ""});
  }
  dense.quantities.push_back({"J M⁻¹ Jᵀ", "3-16", "J B, the matrix PGS sweeps (s × s)",
                              json_of(Eigen::MatrixXd(J * Bt.transpose())), "1/kg"});
  e.push_back(std::move(dense));
  return e;
}

Vec6 System::constraint_force(int b) const {
  Vec6 f = Vec6::Zero();
  for (std::size_t i = 0; i < report.mlcp.rows.size(); ++i) {
    const ConstraintRow& row = report.mlcp.rows[i];
    for (int k = 0; k < 2; ++k) {
      if (row.Jmap[k] == b) f += row.Jsp[k] * report.solution.lambda[static_cast<Eigen::Index>(i)];
    }
  }
  return f;
}

double System::last_residual() const {
  return report.solution.residuals.empty() ? 0.0 : report.solution.residuals.back();
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
