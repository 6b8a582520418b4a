#include "motion/rigid_body.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kinematics/inertia.h"
#include "kinematics/quaternion.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace lamina {
namespace {

// A unit quaternion stays within this of norm 1 after the caller's own normalisation.
constexpr double unit_tolerance = 1e-9;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("rigid body: " + message);
}

void require_pose(const Vec3& x, const Quat& q) {
  require(x.allFinite(), "position is not finite");
  require(q.coeffs().allFinite() && std::abs(q.norm() - 1.0) <= unit_tolerance,
          "orientation is not a unit quaternion (|q| = " + std::to_string(q.norm()) + ")");
}

RigidBody placed(const Vec3& x, const Quat& q) {
  RigidBody body;
  body.x = x;
  body.q = q;
  body.update_derived();
  return body;
}

}  // namespace

RigidBody RigidBody::dynamic_body(double mass, const Mat3& inertia_body, const Vec3& x,
                                  const Quat& q) {
  require(std::isfinite(mass) && mass > 0.0,
          "mass must be finite and positive, got " + std::to_string(mass));
  require(inertia_body.allFinite() && inertia_body.isApprox(inertia_body.transpose()) &&
              inertia_body.llt().info() == Eigen::Success,
          "inertia tensor must be finite, symmetric and positive definite");
  require_pose(x, q);
  RigidBody body;
  body.mass = mass;
  body.inverse_mass = 1.0 / mass;
  body.inertia_body = inertia_body;
  body.inverse_inertia_body = inertia_body.inverse();
  body.x = x;
  body.q = q;
  body.update_derived();
  return body;
}

RigidBody RigidBody::static_body(const Vec3& x, const Quat& q) {
  require_pose(x, q);
  return placed(x, q);
}

void RigidBody::apply_force_at(const Vec3& f, const Vec3& p) {
  // eq. 1-31..1-33
  force += f;
  torque += (p - x).cross(f);
}

void RigidBody::clear_forces() {
  force.setZero();
  torque.setZero();
}

void RigidBody::update_derived() {
  // eq. 2-7: R from q by eq. 1-22
  rotation = quaternion_to_matrix(q);
  // eq. 2-8, applied to the inverse: I⁻¹ = R I0⁻¹ Rᵀ
  inverse_inertia_world = world_inertia(rotation, inverse_inertia_body);
}

Mat3 RigidBody::inertia_world() const { return world_inertia(rotation, inertia_body); }

bool RigidBody::has_finite_state() const {
  return x.allFinite() && q.coeffs().allFinite() && v.allFinite() && angular_velocity.allFinite();
}

Quat planar_orientation(double angle) {
  return quaternion_from_axis_angle(Vec3::UnitZ(), angle);
}

double planar_angle(const Quat& q) {
  // From q = cos(θ/2) + z sin(θ/2): sin θ = 2 w z and cos θ = w² − z². Unlike 2 atan2(z, w),
  // this stays in (−π, π] once q has turned past π (w < 0), and q and −q give the same angle.
  return std::atan2(2.0 * q.w() * q.z(), q.w() * q.w() - q.z() * q.z());
}

RigidBody box_body(double density, double half_x, double half_y, const Vec3& x, double angle) {
  require(std::isfinite(half_x) && std::isfinite(half_y) && half_x > 0.0 && half_y > 0.0,
          "box half extents must be finite and positive, got (" + std::to_string(half_x) + ", " +
              std::to_string(half_y) + ")");
  require(std::isfinite(density) && density > 0.0,
          "density must be finite and positive, got " + std::to_string(density));
  const double mass = density * 4.0 * half_x * half_y * planar_depth;
  return RigidBody::dynamic_body(mass, box_inertia(mass, half_x, half_y), x,
                                 planar_orientation(angle));
}

RigidBody disc_body(double density, double radius, const Vec3& x, double angle) {
  require(std::isfinite(radius) && radius > 0.0,
          "disc radius must be finite and positive, got " + std::to_string(radius));
  require(std::isfinite(density) && density > 0.0,
          "density must be finite and positive, got " + std::to_string(density));
  const double mass = density * M_PI * radius * radius * planar_depth;
  return RigidBody::dynamic_body(mass, disc_inertia(mass, radius), x, planar_orientation(angle));
}

}  // namespace lamina
