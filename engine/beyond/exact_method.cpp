#include "beyond/exact_method.h"

#include "beyond/island_solve.h"
#include "beyond/islands.h"

namespace lamina {
namespace {

class ExactMethod final : public StepMethod {
 public:
  void take_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                 std::vector<double>& lambda, WorldReport* report) override {
    islands_.find(problem.velocity, problem.first_joint_row);
    if (work_.size() < islands_.size()) work_.resize(islands_.size());
    for (std::size_t k = 0; k < islands_.size(); ++k) {
      solve_island(problem.velocity, islands_.begin()[k], problem.settings.step.iterations,
                   work_[k], pgs_, lambda, problem.settings.step.pitfalls);
    }
    if (report != nullptr) {
      report->velocity.solution.residuals = {problem.velocity.residual(lambda.data())};
    }
    finish_step(problem, bodies, lambda, {}, split_, pgs_, report);
  }

 private:
  IslandList islands_;                 // the step's islands
  std::vector<IslandWorkspace> work_;  // each island's solve, by its number
  PgsSolver pgs_;                      // the sweeps of an island past the limit, and of the push-out
  SplitImpulse split_;                 // the position MLCP and the push-out
};

}  // namespace

std::unique_ptr<StepMethod> make_exact_method() { return std::make_unique<ExactMethod>(); }

}  // namespace lamina
