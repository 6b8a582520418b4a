// The plane of Lamina's scenes: 2D vectors and a body's pose in the x–y plane.
//
// Collision detection is written in 2D for clarity (the text leaves it out: docs/the-text.md);
// everything it returns is lifted back to the 3D core with z = 0, so the out-of-plane
// components of every point, normal and Jacobian block are exactly zero.
//
//   p = x + R r      a body point p from its body-frame offset r (eq. 1-25)
//   r = Rᵀ (p − x)   the offset of a world point in the body frame (eq. 5-12)
#pragma once

#include "kinematics/math_types.h"
#include "motion/rigid_body.h"

namespace lamina {

// The pose of a body in the plane: the x–y parts of its x and R.
struct Pose2 {
  Vec2 x = Vec2::Zero();          // centre of mass, world frame, in m
  Mat2 R = Mat2::Identity();      // rotation about z, the top-left block of R

  // eq. 1-25: p = x + R r.
  Vec2 to_world(const Vec2& r) const { return x + R * r; }
  // eq. 5-12: r = Rᵀ (p − x), each component a column of R dotted with p − x (written out:
  // Eigen's product was a call of its own in the narrow phase and the cache's update)
  Vec2 to_body(const Vec2& p) const {
    const Vec2 d = p - x;
    return Vec2(R(0, 0) * d.x() + R(1, 0) * d.y(), R(0, 1) * d.x() + R(1, 1) * d.y());
  }
};

inline Pose2 planar_pose(const RigidBody& body) {
  return Pose2{body.x.head<2>(), body.rotation.topLeftCorner<2, 2>()};
}

// A plane vector as a 3D vector with z = 0.
inline Vec3 lift(const Vec2& v) { return Vec3(v.x(), v.y(), 0.0); }

// The tangent u = z × n of a unit normal n in the plane (a quarter turn counter-clockwise).
inline Vec2 tangent_of(const Vec2& n) { return Vec2(-n.y(), n.x()); }

}  // namespace lamina
