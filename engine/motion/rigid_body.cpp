#include "motion/rigid_body.h"

#include <cmath>
#include <limits>
#include <string>

#include "kinematics/inertia.h"
#include "kinematics/quaternion.h"
#include "kinematics/require.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace lamina {
namespace {

// A unit quaternion stays within this of norm 1 after the caller's own normalisation.
constexpr double unit_tolerance = 1e-9;

void require_pose(const Vec3& x, const Quat& q) {
  require(x.allFinite(), "rigid body: position is not finite");
  require(q.coeffs().allFinite() && std::abs(q.norm() - 1.0) <= unit_tolerance,
          "rigid body: orientation is not a unit quaternion (|q| = " + std::to_string(q.norm()) + ")");
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
  require_positive(mass, "rigid body: mass");
  require(inertia_body.allFinite() && inertia_body.isApprox(inertia_body.transpose()) &&
              inertia_body.llt().info() == Eigen::Success,
          "rigid body: inertia tensor must be finite, symmetric and positive definite");
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
  RigidBody body = placed(x, q);
  // eq. 5-1: infinite mass and inertia; only their inverses, 0, enter the step
  body.mass = std::numeric_limits<double>::infinity();
  body.inertia_body = std::numeric_limits<double>::infinity() * Mat3::Identity();
  return body;
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

Mat3 RigidBody::inertia_world() const {
  // R (∞ E) Rᵀ = ∞ E, which the product would spoil with ∞ × 0 = NaN
  if (is_static()) return inertia_body;
  return world_inertia(rotation, inertia_body);
}

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
  require_positive(half_x, "rigid body: box half extent x");
  require_positive(half_y, "rigid body: box half extent y");
  require_positive(density, "rigid body: density");
  const double mass = density * 4.0 * half_x * half_y * planar_depth;
  return RigidBody::dynamic_body(mass, box_inertia(mass, half_x, half_y), x,
                                 planar_orientation(angle));
}

RigidBody disc_body(double density, double radius, const Vec3& x, double angle) {
  require_positive(radius, "rigid body: disc radius");
  require_positive(density, "rigid body: density");
  const double mass = density * M_PI * radius * radius * planar_depth;
  return RigidBody::dynamic_body(mass, disc_inertia(mass, radius), x, planar_orientation(angle));
}

RigidBody prism_body(double density, const AreaMoments& moments, const Vec3& x, double angle) {
  require_positive(moments.area, "rigid body: area");
  require_positive(density, "rigid body: density");
  const double mass = density * moments.area * planar_depth;
  return RigidBody::dynamic_body(mass, prism_inertia(mass, moments), x, planar_orientation(angle));
}

}  // namespace lamina
