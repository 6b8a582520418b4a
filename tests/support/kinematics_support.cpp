#include "support/kinematics_support.h"

namespace lamina::testing {

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Vec3 random_vec(std::mt19937& rng, double scale) {
  return Vec3(uniform(rng, -scale, scale), uniform(rng, -scale, scale),
              uniform(rng, -scale, scale));
}

Vec3 random_unit(std::mt19937& rng) {
  Vec3 d;
  do d = random_vec(rng, 1.0);
  while (d.norm() < 0.1);
  return d.normalized();
}

Quat random_rotation(std::mt19937& rng) {
  return Quat(Eigen::AngleAxisd(uniform(rng, -M_PI, M_PI), random_unit(rng)));
}

double max_abs(const Mat3& m) { return m.cwiseAbs().maxCoeff(); }

std::vector<PointMass> random_points(std::mt19937& rng, int count) {
  const Vec3 centre = random_vec(rng, 5.0);
  std::vector<PointMass> points;
  for (int i = 0; i < count; ++i)
    points.push_back({uniform(rng, 0.1, 2.0), centre + random_vec(rng, 2.0)});
  return points;
}

RigidMotion RigidMotion::random(std::mt19937& rng) {
  return {random_unit(rng),        random_unit(rng),     uniform(rng, -2.0, 2.0),
          uniform(rng, -2.0, 2.0), random_rotation(rng), random_vec(rng, 3.0),
          random_vec(rng, 3.0),    random_vec(rng, 3.0)};
}

Mat3 RigidMotion::precession_matrix(double t) const {
  return Eigen::AngleAxisd(precession * t, d1).toRotationMatrix();
}

Quat RigidMotion::q(double t) const {
  return Quat(Eigen::AngleAxisd(precession * t, d1)) * Quat(Eigen::AngleAxisd(spin * t, d2)) * q0;
}

}  // namespace lamina::testing
