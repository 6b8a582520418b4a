#include "beyond/exact_method.h"

#include "beyond/island_solve.h"
#include "beyond/islands.h"

namespace lamina {
namespace {

class ExactMethod final : public StepMethod {
 public:
  void take_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                 std::vector<double>& lambda, WorldReport* report) override {
    for (const Island& island : find_islands(problem.velocity, problem.first_joint_row)) {
      solve_island(problem.velocity, island, problem.settings.step.iterations, scratch_, pgs_,
                   lambda, problem.settings.step.pitfalls);
    }
    if (report != nullptr) {
      report->velocity.solution.residuals = {problem.velocity.residual(lambda.data())};
    }
    finish_step(problem, bodies, lambda, {}, split_, pgs_, report);
  }

 private:
  Mlcp scratch_;        // an island's MLCP
  PgsSolver pgs_;       // the sweeps of an island past the limit, and of the push-out
  SplitImpulse split_;  // the position MLCP and the push-out
};

}  // namespace

std::unique_ptr<StepMethod> make_exact_method() { return std::make_unique<ExactMethod>(); }

}  // namespace lamina
