#include "constraints/constrained_step.h"

#include <utility>

namespace lamina {
namespace {

bool same_structure(const std::vector<std::array<int, 2>>& Jmap, const ConstraintRow* first,
                    const ConstraintRow* last) {
  if (Jmap.size() != static_cast<size_t>(last - first)) return false;
  for (size_t i = 0; i < Jmap.size(); ++i) {
    if (Jmap[i] != first[i].Jmap) return false;
  }
  return true;
}

void integrate_all(std::vector<RigidBody>& bodies, double dt, Integration scheme,
                   Pitfalls pitfalls) {
  for (RigidBody& body : bodies) {
    integrate(body, dt, scheme, pitfalls);
    body.clear_forces();
  }
}

}  // namespace

void WarmStart::append_guess(const ConstraintRow* first, const ConstraintRow* last,
                             std::vector<double>& out) const {
  if (same_structure(Jmap, first, last)) {
    out.insert(out.end(), lambda.data(), lambda.data() + lambda.size());
  } else {
    out.insert(out.end(), static_cast<size_t>(last - first), 0.0);
  }
}

void WarmStart::remember(const ConstraintRow* first, const ConstraintRow* last,
                         const double* solved) {
  const auto count = static_cast<Eigen::Index>(last - first);
  Jmap.resize(static_cast<size_t>(count));
  for (Eigen::Index i = 0; i < count; ++i) Jmap[i] = first[i].Jmap;
  lambda = Eigen::Map<const Eigen::VectorXd>(solved, count);
}

void constrained_step(std::vector<RigidBody>& bodies, const ConstraintList& constraints,
                      const ConstrainedStepSettings& settings, WarmStart& warm_start,
                      StepReport* report) {
  const double dt = settings.step.dt;
  apply_gravity(bodies, settings.step.gravity);
  const std::vector<ConstraintRow> rows = write_all_rows(bodies, constraints, dt, settings.step.beta);
  Mlcp mlcp = assemble_mlcp(bodies, rows, dt);
  std::vector<double> lambda;
  if (settings.warm_start && !settings.step.pitfalls.has(Pitfall::no_warm_start)) {
    warm_start.append_guess(rows.data(), rows.data() + rows.size(), lambda);
  } else {
    lambda.assign(rows.size(), 0.0);
  }
  const SweepSettings sweeps{settings.step.iterations, settings.tolerance, report != nullptr};
  SweepResult solution;
  if (report != nullptr) {
    report->lambda_exp = Eigen::Map<const Eigen::VectorXd>(lambda.data(), mlcp.row_count());
  }
  PgsSolver().solve(mlcp, lambda.data(), sweeps, solution, settings.step.pitfalls);
  // eq. 3-11: F_c = Jᵀ λ joins F_ext on every body
  mlcp.add_constraint_forces(bodies, lambda.data());
  integrate_all(bodies, dt, settings.scheme, settings.step.pitfalls);
  warm_start.remember(rows.data(), rows.data() + rows.size(), lambda.data());
  if (report == nullptr) return;
  solution.lambda = Eigen::Map<const Eigen::VectorXd>(lambda.data(), mlcp.row_count());
  report->mlcp = std::move(mlcp);
  report->solution = std::move(solution);
}

}  // namespace lamina
