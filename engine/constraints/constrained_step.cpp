#include "constraints/constrained_step.h"

#include <utility>

namespace lamina {
namespace {

bool same_structure(const std::vector<std::array<int, 2>>& Jmap,
                    const std::vector<ConstraintRow>& rows) {
  if (Jmap.size() != rows.size()) return false;
  for (size_t i = 0; i < rows.size(); ++i) {
    if (Jmap[i] != rows[i].Jmap) return false;
  }
  return true;
}

void integrate_all(std::vector<RigidBody>& bodies, double dt, Integration scheme) {
  for (RigidBody& body : bodies) {
    integrate(body, dt, scheme);
    body.clear_forces();
  }
}

}  // namespace

Eigen::VectorXd WarmStart::guess(const std::vector<ConstraintRow>& rows) const {
  if (same_structure(Jmap, rows)) return lambda;
  return Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows.size()));
}

void WarmStart::append_guess(const std::vector<ConstraintRow>& rows,
                             std::vector<double>& out) const {
  if (same_structure(Jmap, rows)) {
    out.insert(out.end(), lambda.data(), lambda.data() + lambda.size());
  } else {
    out.insert(out.end(), rows.size(), 0.0);
  }
}

void WarmStart::remember(const std::vector<ConstraintRow>& rows,
                         const Eigen::Ref<const Eigen::VectorXd>& solved) {
  Jmap.resize(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) Jmap[i] = rows[i].Jmap;
  lambda = solved;
}

void constrained_step(std::vector<RigidBody>& bodies, const ConstraintList& constraints,
                      const ConstrainedStepSettings& settings, WarmStart& warm_start,
                      StepReport* report) {
  const double dt = settings.dt;
  apply_gravity(bodies, settings.gravity);
  Mlcp mlcp = assemble_mlcp(bodies, write_all_rows(bodies, constraints, dt, settings.beta), dt);
  const Eigen::VectorXd lambda_exp =
      settings.warm_start ? warm_start.guess(mlcp.rows)
                          : Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mlcp.rows.size()));
  PgsSettings pgs = settings.pgs;
  pgs.record_residuals = pgs.record_residuals || report != nullptr;
  PgsResult solution = solve_pgs(mlcp, lambda_exp, pgs);
  // eq. 3-11: F_c = Jᵀ λ joins F_ext on every body
  apply_constraint_forces(bodies, mlcp.rows, solution.lambda);
  integrate_all(bodies, dt, settings.scheme);
  warm_start.remember(mlcp.rows, solution.lambda);
  if (report == nullptr) return;
  report->W = complementarity_slack(mlcp, solution.lambda);
  report->mlcp = std::move(mlcp);
  report->lambda_exp = lambda_exp;
  report->solution = std::move(solution);
}

}  // namespace lamina
