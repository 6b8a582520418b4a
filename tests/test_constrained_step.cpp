// The chapter-3 step (constrained_step.h): a report only observes, and the warm start carries λ
// from step to step only for the same rows. Planar scenes (x–y, y up).
#include <doctest/doctest.h>

#include <vector>

#include "constraints/constrained_step.h"
#include "constraints/jacobian_rows.h"
#include "support/constraint_scenes.h"

using namespace lamina;

namespace {

// The warm start's λ_exp for the rows, appended to nothing.
std::vector<double> guess(const WarmStart& warm_start, const std::vector<ConstraintRow>& rows) {
  std::vector<double> lambda_exp;
  warm_start.append_guess(rows.data(), rows.data() + rows.size(), lambda_exp);
  return lambda_exp;
}

}  // namespace

TEST_SUITE("ConstrainedStep") {
  TEST_CASE("a step that fills a report moves the bodies bit for bit as one that does not") {
    std::vector<RigidBody> plain, reported;
    const ConstraintList constraints = mixed_scene(plain);
    mixed_scene(reported);
    const ConstrainedStepSettings settings;
    WarmStart plain_start, reported_start;
    for (int k = 0; k < 30; ++k) {
      StepReport report;
      constrained_step(plain, constraints, settings, plain_start);
      constrained_step(reported, constraints, settings, reported_start, &report);
    }
    // determinism: the report only observes (exact equality)
    for (size_t b = 0; b < plain.size(); ++b) {
      CHECK(plain[b].x == reported[b].x);
      CHECK(plain[b].q.coeffs() == reported[b].q.coeffs());
      CHECK(plain[b].v == reported[b].v);
      CHECK(plain[b].angular_velocity == reported[b].angular_velocity);
    }
  }

  TEST_CASE("warm start reuses last step's λ only for rows on the same bodies") {
    std::vector<ConstraintRow> rows(2);
    rows[0].Jmap = {0, world};
    rows[1].Jmap = {0, 1};
    WarmStart warm_start;
    const std::vector<double> solved{3.0, 4.0};
    warm_start.remember(rows.data(), rows.data() + rows.size(), solved.data());
    CHECK(guess(warm_start, rows) == std::vector<double>{3.0, 4.0});
    rows[1].Jmap = {1, 0};
    CHECK(guess(warm_start, rows) == std::vector<double>{0.0, 0.0});
    rows.pop_back();
    CHECK(guess(warm_start, rows) == std::vector<double>{0.0});
  }
}
