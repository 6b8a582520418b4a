#include "contact/split_impulse.h"

#include <algorithm>
#include <utility>

#include "motion/integrator.h"

namespace lamina {
namespace {

// λ kept in a std::vector, seen as an Eigen vector (a copy, for a report).
Eigen::VectorXd copy_of(const std::vector<double>& lambda) {
  return Eigen::Map<const Eigen::VectorXd>(lambda.data(), static_cast<Eigen::Index>(lambda.size()));
}

// No point deeper than the slop and no gap to close: every ζ ≤ 0, so λ = 0 solves the position
// MLCP (W = −η ≥ 0, eq. 3-24) and PGS started from λ = 0 keeps it: no push-out this step.
// Box2D's position pass stops early in the same case.
bool nothing_to_push(const std::vector<double>& zeta) {
  return std::all_of(zeta.begin(), zeta.end(), [](double z) { return z <= 0.0; });
}

}  // namespace

void solve_recording(PgsSolver& pgs, const Mlcp& mlcp, int iterations, std::vector<double>& lambda,
                     StepReport* into, Pitfalls pitfalls, std::vector<RigidBody>* forces_to) {
  if (into != nullptr) into->lambda_exp = copy_of(lambda);
  SweepResult sweeps;  // the sweeps run and their residuals; λ itself stays in `lambda`
  pgs.solve(mlcp, lambda.data(), {iterations, 0.0, into != nullptr}, sweeps, pitfalls, forces_to);
  if (into == nullptr) return;
  into->mlcp = mlcp;
  sweeps.lambda = copy_of(lambda);
  into->solution = std::move(sweeps);
}

void SplitImpulse::solve(const Mlcp& velocity, const std::vector<ContactPair>& pairs,
                         const ContactSettings& contact, const StepSettings& step, int iterations,
                         PgsSolver& pgs, StepReport* report, Workers* workers) {
  if (!prepare(velocity, pairs, contact, step, report != nullptr, workers)) return;
  solve_recording(pgs, position_, iterations, lambda_, report, step.pitfalls);
  take_push_out(pgs, step.dt, workers);
}

bool SplitImpulse::prepare(const Mlcp& velocity, const std::vector<ContactPair>& pairs,
                           const ContactSettings& contact, const StepSettings& step,
                           bool reporting, Workers* workers) {
  push_out_.clear();
  if (contact.correction != PositionCorrection::split_impulse) return false;
  // The velocity MLCP's contact rows again, each asking J V_p ≥ its push-out (or gap) ζ
  position_targets(pairs, contact, step, rows_, zeta_, workers);
  if (!reporting && nothing_to_push(zeta_)) return false;  // a report shows the sweeps
  // eq. 3-16 for the push-out alone: the bodies start from rest under no force, so η = ζ/Δt
  position_.assemble_rows_of(velocity, rows_, zeta_, step.dt, workers);
  lambda_.assign(rows_.size(), 0.0);
  return true;
}

void SplitImpulse::take_push_out(const PgsSolver& pgs, double dt, Workers* workers) {
  // The push-out velocity of each body: M⁻¹ Jᵀ λ Δt = B λ Δt (each run of the workers its share)
  push_out_.resize(static_cast<std::size_t>(position_.body_count()));
  const int runs = runs_on(workers);
  run_on(workers, [&](int t) {
    const auto [first, last] = share_of(push_out_.size(), t, runs);
    for (std::size_t b = first; b < last; ++b) {
      push_out_[b] = pgs.velocity_change(static_cast<int>(b)) * dt;
    }
  });
}

void integrate_with_push_out(RigidBody& body, const Vec6& push, double dt, Pitfalls pitfalls) {
  if (body.is_static()) {
    body.clear_forces();
    return;
  }
  // Split impulse: the push-out velocity moves the body in this step and is then taken back.
  body.v += push.head<3>();
  body.angular_velocity += push.tail<3>();
  // eq. 2-1..2-8 under F_ext + F_c
  integrate(body, dt, Integration::semi_implicit, pitfalls);
  body.v -= push.head<3>();
  body.angular_velocity -= push.tail<3>();
  body.clear_forces();
}

void integrate_with_push_out(std::vector<RigidBody>& bodies, const std::vector<Vec6>& push_out,
                             double dt, Pitfalls pitfalls, Workers* workers,
                             const std::vector<unsigned char>& skip) {
  const int runs = runs_on(workers);
  const auto step_run = [&](int t) {
    const auto [first, last] = share_of(bodies.size(), t, runs);
    for (std::size_t i = first; i < last; ++i) {
      if (!skip.empty() && skip[i] != 0) {
        bodies[i].clear_forces();  // advanced already: its F_c was taken in its own steps
        continue;
      }
      integrate_with_push_out(bodies[i], push_out.empty() ? Vec6::Zero() : push_out[i], dt,
                              pitfalls);
    }
  };
  run_on(workers, step_run);
}

}  // namespace lamina
