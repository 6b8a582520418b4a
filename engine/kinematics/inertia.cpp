#include "kinematics/inertia.h"

#include "kinematics/rotation.h"

namespace lamina {

Vec3 centre_of_mass(const std::vector<PointMass>& points) {
  double mass = 0.0;
  Vec3 weighted = Vec3::Zero();
  for (const PointMass& p : points) {
    mass += p.mass;
    weighted += p.mass * p.position;
  }
  // eq. 1-1
  return weighted / mass;
}

Mat3 point_set_inertia(const std::vector<PointMass>& points, const Vec3& centre) {
  Mat3 inertia = Mat3::Zero();
  for (const PointMass& p : points) {
    const Mat3 s = skew(p.position - centre);
    // eq. 1-36: I = Σ −m_i Skew(r_i)²
    inertia -= p.mass * (s * s);
  }
  return inertia;
}

Mat3 box_inertia(double mass, double half_x, double half_y) {
  const double half_z = 0.5 * planar_depth;
  const double xx = half_x * half_x, yy = half_y * half_y, zz = half_z * half_z;
  // The cuboid's closed form, I = m/3 diag(hy² + hz², hx² + hz², hx² + hy²).
  return (mass / 3.0) * Vec3(yy + zz, xx + zz, xx + yy).asDiagonal();
}

Mat3 disc_inertia(double mass, double radius) {
  const double rr = radius * radius;
  const double ll = planar_depth * planar_depth;
  // The cylinder's closed form: I_xx = I_yy = m (3r² + l²)/12, I_zz = m r²/2.
  const double across = mass * (3.0 * rr + ll) / 12.0;
  return Vec3(across, across, 0.5 * mass * rr).asDiagonal();
}

Mat3 world_inertia(const Mat3& rotation, const Mat3& body_inertia) {
  // eq. 1-37
  return rotation * body_inertia * rotation.transpose();
}

}  // namespace lamina
