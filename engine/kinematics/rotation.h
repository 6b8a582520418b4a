// Rotation matrices from an axis and an angle (chapter 1, "Rotation").
#pragma once

#include "kinematics/math_types.h"

namespace lamina {

// eq. 1-2: Skew(d) = [[0,-dz,dy],[dz,0,-dx],[-dy,dx,0]], so that Skew(d) r = d × r (eq. 1-3).
inline Mat3 skew(const Vec3& d) {
  Mat3 s;
  s << 0.0, -d.z(), d.y(),
       d.z(), 0.0, -d.x(),
       -d.y(), d.x(), 0.0;
  return s;
}

// eq. 1-4 (Rodrigues): R = E + sinθ Skew(d) + (1 − cosθ) Skew(d)², for a unit axis d.
Mat3 rodrigues(const Vec3& unit_axis, double angle);

// eq. 1-5: rotation about the z axis by θ (the only rotation a planar scene needs).
Mat3 rotation_z(double angle);

}  // namespace lamina
