#include "constraints/distance_constraint.h"

#include <cmath>

namespace lamina {

DistanceConstraint::DistanceConstraint(const Anchor& a, const Anchor& b, double length)
    : a_(a), b_(b), length_(length) {
  const std::string what = "distance constraint";
  require_body_pair(a.body, b.body, what);
  require_input(a.local.allFinite() && b.local.allFinite(), what, "an anchor is not finite");
  require_input(std::isfinite(length) && length > 0.0, what,
                "length L must be finite and positive, got " + std::to_string(length));
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
