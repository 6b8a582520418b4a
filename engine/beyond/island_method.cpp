#include "beyond/island_method.h"

#include "beyond/island_solve.h"
#include "beyond/islands.h"
#include "motion/integrator.h"

namespace lamina {
namespace {

// Moves a body by its push-out [v; ω] over Δt, as chapter 2's step moves it by a velocity
// (eq. 2-5, 2-6), leaving its velocity as it was.
void push_out_body(RigidBody& body, const Vec6& push, double dt, Pitfalls pitfalls) {
  const Vec3 v = body.v, omega = body.angular_velocity;
  body.v = push.head<3>();
  body.angular_velocity = push.tail<3>();
  integrate(body, dt, Integration::semi_implicit, pitfalls);
  body.v = v;
  body.angular_velocity = omega;
}

class IslandMethod final : public StepMethod {
 public:
  void take_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                 std::vector<double>& lambda, WorldReport* report) override {
    const WorldSettings& s = problem.settings;
    skip_.assign(bodies.size(), 0);
    pgs_.use_workers(problem.workers);  // a large island's sweeps, and the push-out's, on them
    islands_.find(problem.velocity, problem.first_joint_row);
    if (work_.size() < islands_.size()) work_.resize(islands_.size());
    // Without a report, the largest island that PGS sweeps (past the exact solve's size) is
    // swept last, beside split impulse's position MLCP, made ready first (its ζ does not depend
    // on the velocity λ); the islands' order changes no number, their rows and bodies apart.
    std::size_t beside = islands_.size();
    if (report == nullptr) {
      for (std::size_t k = 0; k < islands_.size(); ++k) {
        const Island& island = islands_.begin()[k];
        if (island.lcp_size <= exact_island_limit) continue;
        const bool larger = beside == islands_.size() ||
                            island.rows.size() > islands_.begin()[beside].rows.size();
        if (larger) beside = k;
      }
    }
    const bool push_out_taken = beside < islands_.size();
    const bool to_push = push_out_taken && split_.prepare(problem.velocity, problem.pairs,
                                                          s.contact, s.step, false,
                                                          problem.workers);
    for (std::size_t k = 0; k < islands_.size(); ++k) {
      const Island& island = islands_.begin()[k];
      if (k == beside) continue;
      if (island.joint_rows > 0 && island.lcp_size <= exact_island_limit) {
        substep(problem, island, work_[k], bodies, lambda);
        for (const int b : island.bodies) skip_[static_cast<std::size_t>(b)] = 1;
      } else {
        solve_island(problem.velocity, island, s.step.iterations, work_[k], pgs_, lambda,
                     s.step.pitfalls);
      }
    }
    bool forces_added = false;  // F_c = Jᵀ λ, by a pile's sweeps
    if (to_push) {
      forces_added = solve_island_beside(problem.velocity, islands_.begin()[beside],
                                         s.step.iterations, work_[beside], pgs_, lambda, split_,
                                         s.position_iterations, bodies, s.step.pitfalls);
      split_.take_push_out(pgs_, s.step.dt, problem.workers);
    } else if (push_out_taken) {
      // nothing to push out (split_.prepare left the push-out empty): the island alone
      solve_island(problem.velocity, islands_.begin()[beside], s.step.iterations, work_[beside],
                   pgs_, lambda, s.step.pitfalls);
    }
    if (report != nullptr) {
      report->velocity.solution.residuals = {problem.velocity.residual(lambda.data())};
    }
    finish_step(problem, bodies, lambda, skip_, split_, pgs_, report, push_out_taken,
                forces_added);
    const std::vector<Vec6>& push = split_.push_out();
    if (push.empty()) return;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (skip_[b]) push_out_body(bodies[b], push[b], s.step.dt, s.step.pitfalls);
    }
  }

 private:
  // Advances the island's bodies by Δt in joint_substeps substeps, each solving the island's rows
  // exactly (contact rows as step 4 wrote them, joints' rows written again at the substep's
  // poses with Δt / joint_substeps) and taking chapter 2's step. λ becomes the substeps' mean.
  void substep(const StepProblem& problem, const Island& island, IslandWorkspace& work,
               std::vector<RigidBody>& bodies, std::vector<double>& lambda) {
    const double h = problem.settings.step.dt / joint_substeps;
    const double beta = problem.settings.step.beta;
    // The island's rows, numbered from 0; a friction row's contact row renumbered with them.
    rows_.clear();
    local_of_.assign(static_cast<std::size_t>(problem.velocity.row_count()), -1);
    for (const int r : island.rows) {
      local_of_[static_cast<std::size_t>(r)] = static_cast<int>(rows_.size());
      rows_.push_back(problem.velocity.row(r));
    }
    for (ConstraintRow& row : rows_) {
      if (row.friction_of < 0) continue;
      row.friction_of = local_of_[static_cast<std::size_t>(row.friction_of)];
    }
    // Each joint of the island and where its rows sit among the island's.
    joints_.clear();
    for (std::size_t j = 0; j < problem.joints.size(); ++j) {
      const RowRange range = problem.joint_rows[j];
      if (range.count > 0 && local_of_[static_cast<std::size_t>(range.first)] >= 0) {
        joints_.emplace_back(problem.joints[j], local_of_[static_cast<std::size_t>(range.first)]);
      }
    }
    external_.clear();  // F_ext, kept for every substep
    for (const int b : island.bodies) {
      external_.push_back(external_force_of(bodies[static_cast<std::size_t>(b)]));
    }
    local_.clear();
    for (const int r : island.rows) local_.push_back(lambda[static_cast<std::size_t>(r)]);
    mean_.assign(island.rows.size(), 0.0);
    all_.lcp_size = island.lcp_size;  // the substep's MLCP is the island's rows, all of them
    all_.rows.clear();
    for (int i = 0; i < static_cast<int>(local_.size()); ++i) all_.rows.push_back(i);
    bool pivoting = true;
    for (int s = 0; s < joint_substeps; ++s) {
      for (const auto& [joint, first] : joints_) {
        written_.clear();
        joint->write_rows(bodies, h, beta, written_);
        for (std::size_t k = 0; k < written_.size(); ++k) {
          rows_[static_cast<std::size_t>(first) + k] = written_[k];
        }
      }
      for (std::size_t k = 0; k < external_.size(); ++k) {
        RigidBody& body = bodies[static_cast<std::size_t>(island.bodies[k])];
        body.force = external_[k].head<3>();
        body.torque = external_[k].tail<3>();
      }
      // eq. 3-16 for the substep, solved exactly (PGS if Lemke gives up). Once Lemke has given
      // up in a step, the step's later substeps go to PGS without asking it again: their MLCPs
      // differ little, and a failed pivoting costs hundreds of PGS sweeps (a box on
      // a nearly straight bridge, whose dependent pins Lemke cannot resolve: 8× the time).
      unconstrained_velocities(bodies, h, unconstrained_);
      substep_mlcp_.assemble(bodies, rows_, unconstrained_, h);
      const IslandSolve how =
          solve_island(substep_mlcp_, all_, problem.settings.step.iterations, work, pgs_, local_,
                       problem.settings.step.pitfalls, pivoting);
      pivoting = how == IslandSolve::exact;
      // eq. 3-11: F_c = Jᵀ λ, then chapter 2's step over h
      substep_mlcp_.add_constraint_forces(bodies, local_.data());
      for (const int b : island.bodies) {
        RigidBody& body = bodies[static_cast<std::size_t>(b)];
        integrate(body, h, Integration::semi_implicit, problem.settings.step.pitfalls);
        body.clear_forces();
      }
      for (std::size_t i = 0; i < local_.size(); ++i) mean_[i] += local_[i] / joint_substeps;
    }
    for (std::size_t i = 0; i < mean_.size(); ++i) {
      lambda[static_cast<std::size_t>(island.rows[i])] = mean_[i];
    }
  }

  IslandList islands_;                   // the step's islands
  std::vector<IslandWorkspace> work_;    // each island's solve, by its number
  Mlcp substep_mlcp_;                    // a substep's MLCP of the island's rows
  PgsSolver pgs_;                        // sweeps of large islands and of the push-out
  SplitImpulse split_;                   // the position MLCP and the push-out
  std::vector<unsigned char> skip_;      // bodies a substepped island has advanced already
  // a substepped island's:
  std::vector<ConstraintRow> rows_;      // rows
  std::vector<int> local_of_;            // each of the step's rows' number among them (−1: none)
  std::vector<std::pair<const Constraint*, int>> joints_;  // joints and their first rows
  std::vector<Vec6> external_;           // F_ext of its bodies
  std::vector<double> local_, mean_;     // λ of a substep, and the substeps' mean
  Island all_;                           // every one of its rows
  std::vector<ConstraintRow> written_;   // a joint's rows written again
  std::vector<Vec6> unconstrained_;      // V/h + M⁻¹ F_ext per body, for a substep
};

}  // namespace

std::unique_ptr<StepMethod> make_island_method() { return std::make_unique<IslandMethod>(); }

}  // namespace lamina
