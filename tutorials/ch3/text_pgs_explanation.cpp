#include "ch3/text_pgs_explanation.h"

#include <vector>

#include "constraints/text_pgs.h"
#include "language/language.h"
#include "motion/integrator.h"

namespace lamina::ch3 {
namespace {

using tutorial::json_of;

Eigen::VectorXd vector_of(const std::vector<double>& x) {
  return Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
}

// s × 12: each row's two blocks side by side, [block 0 | block 1].
Eigen::MatrixXd side_by_side(const text::Blocks& blocks) {
  Eigen::MatrixXd m(static_cast<Eigen::Index>(blocks.size()), 12);
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    m.row(static_cast<Eigen::Index>(i)) << blocks[i][0].transpose(), blocks[i][1].transpose();
  }
  return m;
}

// s × 2: each row's two bodies.
Eigen::MatrixXd body_map(const text::BodyMap& Jmap) {
  Eigen::MatrixXd m(static_cast<Eigen::Index>(Jmap.size()), 2);
  for (std::size_t i = 0; i < Jmap.size(); ++i) m.row(static_cast<Eigen::Index>(i)) << Jmap[i][0], Jmap[i][1];
  return m;
}

// One 6-vector per body, as the rows of an n × 6 matrix.
Eigen::MatrixXd per_body(const std::vector<text::Vector6>& a) {
  Eigen::MatrixXd m(static_cast<Eigen::Index>(a.size()), 6);
  for (std::size_t b = 0; b < a.size(); ++b) m.row(static_cast<Eigen::Index>(b)) = a[b].transpose();
  return m;
}

// One λ per sweep, as the rows of a sweeps × s matrix.
Eigen::MatrixXd per_sweep(const std::vector<std::vector<double>>& lambdas, std::size_t s) {
  Eigen::MatrixXd m(static_cast<Eigen::Index>(lambdas.size()), static_cast<Eigen::Index>(s));
  for (std::size_t k = 0; k < lambdas.size(); ++k) m.row(static_cast<Eigen::Index>(k)) = vector_of(lambdas[k]);
  return m;
}

}  // namespace

tutorial::Section text_pgs_section(const System& s, const std::string& title) {
  // constrained_step keeps the MLCP packed for its own sweep; the text's PGS starts from the rows:
  // they are written again at t, with F_ext = m g on the bodies as the step had it
  const StepSettings& step = s.settings.step;
  std::vector<RigidBody> bodies = s.at_t;
  apply_gravity(bodies, step.gravity);
  const std::vector<ConstraintRow> rows = write_all_rows(bodies, s.constraints, step.dt, step.beta);
  const text::Problem problem = text::make_problem(bodies, rows, step.dt);
  const Eigen::VectorXd& start = s.report.lambda_exp;
  const std::vector<double> lambda_exp(start.data(), start.data() + start.size());
  text::Trace trace;
  const std::vector<double> lambda =
      text::ProjectedGaussSeidel(problem, lambda_exp, s.report.solution.iterations, &trace);
  const Eigen::VectorXd& packed = s.report.solution.lambda;
  tutorial::Section section{title, {}};
  auto add = [&](tutorial::Quantity q) { section.quantities.push_back(std::move(q)); };
  add({"Jmap", "", tr("Jmap[s][2]: each row's two bodies, −1 for none"),
       json_of(body_map(problem.Jmap)), ""});
  add({"Jsp", "3-8", tr("Jsp[s][2]: each row's J blocks, [v ω | v ω]"),
       json_of(side_by_side(problem.Jsp)), ""});
  add({"Bsp", "3-16",
       tr("Convert: Bsp[i][k] = M⁻¹[Jmap[i][k]] Jsp[i][k], the blocks of Bᵀ = J M⁻¹"),
       json_of(side_by_side(trace.Bsp)), ""});
  add({"d", "", tr("d[i] = Jsp[i][0]·Bsp[i][0] + Jsp[i][1]·Bsp[i][1], the diagonal of J B"),
       json_of(vector_of(trace.d)), ""});
  add({"η", "3-16", "ζ/Δt − Multiply(Jsp, Jmap, V/Δt + M⁻¹F_ext)", json_of(vector_of(problem.eta)), "m/s²"});
  add({"a = B λ_exp", "",
       tr("TransposeMultiply(Bsp, Jmap, λ_exp): [v ω] per body, before the sweeps"),
       json_of(per_body(trace.a_start)), ""});
  add({tr("λ after each sweep"), "3-24", tr("one line per sweep, each λ_i clamped to [λ⁻_i, λ⁺_i]"),
       json_of(per_sweep(trace.lambda_after_sweep, rows.size())), "N"});
  add({"a = B λ", "", tr("after the last sweep, per body"), json_of(per_body(trace.a)), ""});
  add({tr("λ (the text's PGS)"), "3-24", tr("ProjectedGaussSeidel's answer"),
       json_of(vector_of(lambda)), "N"});
  add({"λ (PgsSolver)", "3-24", tr("the packed solver's answer, the one the step used"),
       json_of(packed), "N"});
  add({"max |Δλ|", "", tr("the two answers' largest difference (round-off)"),
       (vector_of(lambda) - packed).cwiseAbs().maxCoeff(), "N"});
  return section;
}

}  // namespace lamina::ch3
