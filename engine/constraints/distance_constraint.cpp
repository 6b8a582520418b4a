#include "constraints/distance_constraint.h"

#include <cmath>
#include <string>

#include "kinematics/require.h"

namespace lamina {

DistanceConstraint::DistanceConstraint(const Anchor& a, const Anchor& b, double length)
    : a_(a), b_(b), length_(length) {
  const std::string what = "distance constraint";
  require_body_pair(a.body, b.body, what);
  require(a.local.allFinite() && b.local.allFinite(), what + ": an anchor is not finite");
  // A rod of length 0 has no direction u = d/|d| to hold
  require(std::isfinite(length) && length > 0.0,
          what + ": the rod's two ends coincide or its length L is not finite and positive: a rod "
                 "needs a length (a revolute joint pins two bodies at one point)");
}

void DistanceConstraint::write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                                    std::vector<ConstraintRow>& rows) const {
  const Vec3 d = anchor_position(bodies, b_) - anchor_position(bodies, a_);
  const double distance = d.norm();
  // u = d / |d|; if the ends meet, any direction separates them, and y is as good as any
  const Vec3 u = distance > 0.0 ? Vec3(d / distance) : Vec3::UnitY();
  ConstraintRow row = point_row(bodies, a_, b_, u);
  // eq. 3-14 with C = |d| − L
  row.zeta = equality_bias(distance - length_, dt, beta);
  rows.push_back(row);
}

}  // namespace lamina
