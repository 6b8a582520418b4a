#include "kinematics/rotation.h"

#include <cmath>

namespace lamina {

Mat3 rodrigues(const Vec3& unit_axis, double angle) {
  const Mat3 s = skew(unit_axis);
  // eq. 1-4
  return identity3() + std::sin(angle) * s + (1.0 - std::cos(angle)) * (s * s);
}

Mat3 rotation_z(double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  Mat3 r;
  // eq. 1-5
  r << c, -s, 0.0,
       s, c, 0.0,
       0.0, 0.0, 1.0;
  return r;
}

}  // namespace lamina
