// Momentum, angular momentum and kinetic energy of a rigid body (eq. 1-38..1-48).
#pragma once

#include "kinematics/math_types.h"

namespace lamina {

// eq. 1-38: P = m v.
Vec3 linear_momentum(double mass, const Vec3& v);

// eq. 1-41: L = I ω (world inertia, world angular velocity).
Vec3 angular_momentum(const Mat3& world_inertia, const Vec3& angular_velocity);

// eq. 1-44..1-46: ω̇ = I⁻¹ (L × ω + τ), the full rate of change of ω, gyroscopic term kept.
Vec3 angular_acceleration(const Mat3& world_inertia, const Vec3& angular_velocity,
                          const Vec3& torque);

// eq. 1-47: E = ½ m vᵀv + ½ ωᵀ I ω.
double kinetic_energy(double mass, const Vec3& v, const Mat3& world_inertia,
                      const Vec3& angular_velocity);

// eq. 1-48: Ė = F·v + τ·ω, the power of the applied force and torque.
double power(const Vec3& force, const Vec3& v, const Vec3& torque, const Vec3& angular_velocity);

}  // namespace lamina
