#include "constraints/revolute_joint.h"

#include "kinematics/require.h"

namespace lamina {

RevoluteJoint::RevoluteJoint(const Anchor& a, const Anchor& b) : a_(a), b_(b) {
  const std::string what = "revolute joint";
  require_body_pair(a.body, b.body, what);
  require(a.local.allFinite() && b.local.allFinite(), what + ": an anchor is not finite");
}

void RevoluteJoint::write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                               std::vector<ConstraintRow>& rows) const {
  const Vec3 C = anchor_position(bodies, b_) - anchor_position(bodies, a_);
  const Vec3 axes[] = {Vec3::UnitX(), Vec3::UnitY()};
  for (const Vec3& e : axes) {
    ConstraintRow row = point_row(bodies, a_, b_, e);
    // eq. 3-14 with C_k = e_k · (p_b − p_a)
    row.zeta = equality_bias(C.dot(e), dt, beta);
    rows.push_back(row);
  }
}

}  // namespace lamina
