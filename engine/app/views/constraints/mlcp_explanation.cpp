#include "app/views/constraints/mlcp_explanation.h"

#include "constraints/dense_system.h"
#include "language/language.h"

namespace lamina::view {
namespace {

using tutorial::Json;
using tutorial::json_of;

constexpr int dense_bodies = 2;  // J and M⁻¹ have 6n columns: 12 fit a terminal
constexpr int dense_rows = 8;    // J M⁻¹ Jᵀ is s × s

std::string body_name(const std::vector<std::string>& bodies, int b) {
  return b < 0 ? std::string(tr("none")) : bodies.at(static_cast<std::size_t>(b));
}

}  // namespace

Section row_section(const StepReport& report, int i, const std::string& title,
                    const std::vector<std::string>& bodies) {
  const Mlcp& mlcp = report.mlcp;
  const double* lambda = report.solution.lambda.data();
  const auto r = static_cast<Eigen::Index>(i);
  const std::array<int, 2> map = mlcp.bodies_of(i);
  const auto [lo, hi] = mlcp.bounds(i, lambda);
  Section s{title, {}};
  s.quantities.push_back({"Jmap", "",
                          tr("the row's bodies (a static body or the world holds no block)"),
                          Json::array({body_name(bodies, map[0]), body_name(bodies, map[1])}), ""});
  s.quantities.push_back({"Jsp[0]", "3-8",
                          fill(tr("J block of {0}, [v ω]"), {body_name(bodies, map[0])}),
                          json_of(Eigen::VectorXd(mlcp.jacobian(i, 0))), ""});
  if (map[1] >= 0) {
    s.quantities.push_back({"Jsp[1]", "3-8",
                            fill(tr("J block of {0}, [v ω]"), {body_name(bodies, map[1])}),
                            json_of(Eigen::VectorXd(mlcp.jacobian(i, 1))), ""});
  }
  s.quantities.push_back({"ζ", "3-15", tr("the velocity asked of J V(t+Δt)"), mlcp.zeta(i), "m/s"});
  s.quantities.push_back({"η", "3-16", "ζ/Δt − J (V/Δt + M⁻¹ F_ext)", mlcp.eta(i), "m/s²"});
  s.quantities.push_back({"d", "3-16", tr("J_i M⁻¹ J_iᵀ, the diagonal of J B"), mlcp.d(i), ""});
  s.quantities.push_back({"[λ⁻, λ⁺]", "3-24, 3-26", tr("bounds as solved (friction: ±μ λc)"),
                          tutorial::bounds_text(lo, hi), "N"});
  s.quantities.push_back(
      {"λ_exp", "", tr("PGS's starting guess (the warm start, or 0)"), report.lambda_exp[r], "N"});
  s.quantities.push_back(
      {"λ", "3-24", tr("PGS's answer; the impulse over the step is λ Δt"), lambda[i], "N"});
  s.quantities.push_back(
      {"W", "3-23", tr("(J B λ − η)_i: 0 inside the bounds"), report.slack()[r], "m/s²"});
  return s;
}

Section sweeps_section(const StepReport& report, const std::string& title) {
  const std::vector<double>& residuals = report.solution.residuals;
  Json values = Json::array();
  for (double x : residuals) values.push_back(x);
  return {title,
          {{tr("sweeps"), "", tr("Gauss-Seidel sweeps run (MAX_ITERATION of the text)"),
            report.solution.iterations, ""},
           {"‖W‖", "3-23, 3-24", tr("MLCP residual after each sweep"), values, "m/s²"}}};
}

std::optional<Section> dense_section(const StepReport& report, const std::vector<RigidBody>& bodies,
                                     const std::string& title) {
  const Mlcp& mlcp = report.mlcp;
  if (mlcp.row_count() == 0 || mlcp.row_count() > dense_rows) return std::nullopt;
  const Eigen::MatrixXd J = dense_jacobian(mlcp);
  Section s{title, {}};
  if (mlcp.body_count() <= dense_bodies) {
    s.quantities.push_back({"J", "3-8", tr("s × 6n Jacobian"), json_of(J), ""});
    s.quantities.push_back({"M⁻¹", "3-12, 5-1", tr("diag(m⁻¹E, I⁻¹) per body, 0 for a static body"),
                            json_of(dense_inverse_mass(bodies)), ""});
  }
  // eq. 3-16: J B with Bᵀ = J M⁻¹ (the text's Convert)
  s.quantities.push_back({"J M⁻¹ Jᵀ", "3-16", tr("the MLCP's matrix J B (s × s)"),
                          json_of(Eigen::MatrixXd(J * dense_b_transpose(mlcp).transpose())), ""});
  return s;
}

Section body_section(const std::string& title, const RigidBody& body, const StateTags& tags) {
  return {title,
          {{"x", tags.x, tr("centre of mass"), json_of(body.x), "m"},
           {"θ", tags.theta, tr("angle about z"), planar_angle(body.q), "rad"},
           {"v", tags.v, tr("velocity"), json_of(body.v), "m/s"},
           {"ω", tags.omega, tr("angular velocity"), json_of(body.angular_velocity), "rad/s"}}};
}

Quantity constraint_force(const StepReport& report, int body) {
  return {"F_c", "3-11", tr("Jᵀ λ on the body, [f_c; τ_c] in N and N·m"),
          json_of(Eigen::VectorXd(report.constraint_wrench(body))), ""};
}

std::vector<std::string> numbered_bodies(std::size_t count) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < count; ++i)
    names.push_back(fill(tr("body {0}"), {std::to_string(i)}));
  return names;
}

void add_viewer_rows(const StepReport& report, const std::vector<std::string>& titles,
                     tutorial::ViewerStep& step) {
  const Mlcp& mlcp = report.mlcp;
  const SweepResult& solution = report.solution;
  const double* lambda = solution.lambda.data();
  const Eigen::VectorXd slack = report.slack();  // W = J B λ − η, eq. 3-23, once for all rows
  for (int i = 0; i < mlcp.row_count(); ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    tutorial::ViewerRow row;
    row.kind = mlcp.friction_of(i) >= 0 ? "friction" : "row";
    row.title = titles.at(static_cast<std::size_t>(i));
    row.bodies = mlcp.bodies_of(i);
    for (int k = 0; k < 2; ++k) {
      const Vec6 j = mlcp.jacobian(i, k);  // [v ω]: the plane's columns are v_x, v_y, ω_z
      row.J[static_cast<std::size_t>(k)] = {j[0], j[1], j[5]};
    }
    row.d = mlcp.d(i);
    row.eta = mlcp.eta(i);
    const auto [lo, hi] = mlcp.bounds(i, lambda);
    row.lower = lo;
    row.upper = hi;
    row.lambda_exp = r < report.lambda_exp.size() ? report.lambda_exp[r] : 0.0;
    row.lambda = lambda[i];
    row.slack = slack[r];
    for (const Eigen::VectorXd& after : solution.lambdas) row.sweeps.push_back(after[r]);
    step.rows.push_back(std::move(row));
  }
  step.residuals = solution.residuals;
}

}  // namespace lamina::view
