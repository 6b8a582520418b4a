#include "app/views/constraints/constraint_view.h"

namespace lamina::view {

std::optional<render::Joint> joint_view(const std::vector<RigidBody>& bodies,
                                        const Constraint& joint) {
  const std::optional<std::array<Anchor, 2>> ends = joint.ends();
  if (!ends) return std::nullopt;
  // eq. 1-25: each end at p = x + R r0
  return render::Joint{anchor_position(bodies, (*ends)[0]).head<2>(),
                       anchor_position(bodies, (*ends)[1]).head<2>()};
}

}  // namespace lamina::view
