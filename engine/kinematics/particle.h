// A particle fixed in a rigid body: where it is, how fast it moves, how it accelerates.
#pragma once

#include "kinematics/math_types.h"

namespace lamina {

// eq. 1-24, 1-25: x_i(t) = x(t) + R(t) r_i(0), with r_i(0) the particle's body-frame offset.
Vec3 particle_position(const Vec3& x, const Mat3& rotation, const Vec3& body_offset);

// eq. 1-30: v_i = v + ω × (x_i − x).
Vec3 particle_velocity(const Vec3& v, const Vec3& angular_velocity, const Vec3& x,
                       const Vec3& particle);

// eq. 1-49: a_i = v̇ + ω̇ × r + ω × (ω × r), with r = x_i − x.
Vec3 particle_acceleration(const Vec3& linear_acceleration, const Vec3& angular_acceleration,
                           const Vec3& angular_velocity, const Vec3& r);

}  // namespace lamina
