#include "constraints/incline_constraint.h"

#include <cmath>

#include "constraints/jacobian_rows.h"
#include "kinematics/require.h"

namespace lamina {

InclineConstraint::InclineConstraint(int body, const Vec3& p, const Vec3& normal, InclineKind kind)
    : body_(body), p_(p), normal_(normal), kind_(kind) {
  const std::string what = "incline constraint";
  require(body >= 0, what + ": needs a body index ≥ 0, got " + std::to_string(body));
  require(p.allFinite(), what + ": point p is not finite");
  require(normal.allFinite() && std::abs(normal.norm() - 1.0) <= 1e-9,
          what + ": normal N must be a unit vector, |N| = " + std::to_string(normal.norm()));
}

void InclineConstraint::write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                                   std::vector<ConstraintRow>& rows) const {
  // J = [ Nᵀ 0ᵀ ]: the incline is the world side, the body's centre the other
  ConstraintRow row = point_row(bodies, Anchor{world, p_}, Anchor{body_, Vec3::Zero()}, normal_);
  // eq. 3-13: ε = (x − p) · N
  const double C = (bodies[body_].x - p_).dot(normal_);
  if (kind_ == InclineKind::bilateral) {
    // eq. 3-14
    row.zeta = equality_bias(C, dt, beta);
  } else {
    // eq. 3-17..3-19: C ≥ 0, and eq. 3-26 (ii): a one-sided row
    row.zeta = inequality_bias(C, dt, beta);
    row.lambda_min = 0.0;
  }
  rows.push_back(row);
}

}  // namespace lamina
