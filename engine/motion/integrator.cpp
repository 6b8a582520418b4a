#include "motion/integrator.h"

#include "kinematics/quaternion.h"

namespace lamina {
namespace {

// eq. 2-6: q(t+Δt) = q + ½ ω̂ q Δt, then renormalised. The text stops at the sum; without the
// normalisation |q| grows by O(|ω|² Δt²) every step and R stops being a rotation.
Quat advance_orientation(const Quat& q, const Vec3& angular_velocity, double dt, bool renormalise) {
  const Quat q_dot = quaternion_derivative(angular_velocity, q);  // eq. 1-29
  Quat next(q.w() + q_dot.w() * dt, q.x() + q_dot.x() * dt, q.y() + q_dot.y() * dt,
            q.z() + q_dot.z() * dt);
  if (renormalise) next.normalize();  // the pitfall no-renormalisation leaves the sum
  return next;
}

}  // namespace

void integrate(RigidBody& body, double dt, Integration scheme, Pitfalls pitfalls) {
  const Vec3 v_old = body.v;
  const Vec3 omega_old = body.angular_velocity;
  // eq. 2-1, 2-3: v(t+Δt) = v + m⁻¹ F Δt
  body.v += body.inverse_mass * body.force * dt;
  // eq. 2-2, 2-4: ω(t+Δt) = ω + I⁻¹ τ Δt (gyroscopic term L × ω dropped, as the text does)
  body.angular_velocity += body.inverse_inertia_world * body.torque * dt;
  const bool semi = scheme == Integration::semi_implicit;
  // eq. 2-5: x(t+Δt) = x + v(t+Δt) Δt (explicit variant: v(t))
  body.x += (semi ? body.v : v_old) * dt;
  // eq. 2-6 (explicit variant: ω(t))
  body.q = advance_orientation(body.q, semi ? body.angular_velocity : omega_old, dt,
                               !pitfalls.has(Pitfall::no_renormalisation));
  // eq. 2-7, 2-8
  body.update_derived();
}

void apply_gravity(RigidBody& body, const Vec3& gravity) {
  // eq. 5-2: F_ext = [m1 g, 0, 0, 0]: a fixed body is not pushed by its weight
  if (!body.is_static()) body.force += body.mass * gravity;
}

void apply_gravity(std::vector<RigidBody>& bodies, const Vec3& gravity) {
  for (RigidBody& body : bodies) apply_gravity(body, gravity);
}

void step_unconstrained(std::vector<RigidBody>& bodies, const Vec3& gravity, double dt,
                        Integration scheme) {
  apply_gravity(bodies, gravity);
  for (RigidBody& body : bodies) {
    integrate(body, dt, scheme);
    body.clear_forces();
  }
}

}  // namespace lamina
