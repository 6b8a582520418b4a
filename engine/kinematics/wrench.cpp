#include "kinematics/wrench.h"

namespace lamina {

void Wrench::add_at_point(const Vec3& force_i, const Vec3& point, const Vec3& x) {
  // eq. 1-31: F = Σ F_i
  force += force_i;
  // eq. 1-32, 1-33: τ_i = (x_i − x) × F_i, summed into τ = Σ τ_i
  torque += (point - x).cross(force_i);
}

}  // namespace lamina
