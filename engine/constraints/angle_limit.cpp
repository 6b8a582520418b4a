#include "constraints/angle_limit.h"

#include <cmath>

#include "constraints/jacobian_rows.h"
#include "kinematics/require.h"

namespace lamina {

AngleLimit::AngleLimit(int body_a, int body_b, double limit, LimitSide side)
    : body_a_(body_a), body_b_(body_b), limit_(limit), side_(side) {
  const std::string what = "angle limit";
  require_body_pair(body_a, body_b, what);
  require(std::isfinite(limit) && limit > -M_PI && limit <= M_PI,
          what + ": limit must lie in (−π, π], got " + std::to_string(limit));
}

void AngleLimit::write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                            std::vector<ConstraintRow>& rows) const {
  const double s = side_ == LimitSide::lower ? 1.0 : -1.0;
  const Quat relative = orientation_of(bodies, body_a_).conjugate() * orientation_of(bodies, body_b_);
  // eq. 3-17: C = s (θ − θ_L) ≥ 0
  const double C = s * (planar_angle(relative) - limit_);
  ConstraintRow row = angular_row(bodies, body_a_, body_b_, s * Vec3::UnitZ());
  // eq. 3-18, 3-19, 3-14
  row.zeta = inequality_bias(C, dt, beta);
  // eq. 3-26 (ii): a one-sided row
  row.lambda_min = 0.0;
  row.lambda_max = infinity;
  rows.push_back(row);
}

}  // namespace lamina
