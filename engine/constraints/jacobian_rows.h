// The two kinds of Jacobian row the chapter's constraints are built from.
//
//   anchor     a point fixed in body b: p = x_b + R_b r0 (eq. 1-25), r = p − x_b;
//              or, for b = world (−1), a fixed point of the world: p = r0, r = 0
//   point row  Ċ = u · (ṗ_b − ṗ_a) = u·(v_b + ω_b × r_b) − u·(v_a + ω_a × r_a)   (eq. 1-30)
//              J = [ −uᵀ  −(r_a × u)ᵀ   uᵀ  (r_b × u)ᵀ ]   (uses u·(ω × r) = ω·(r × u))
//   angular row  Ċ = e · (ω_b − ω_a)
//              J = [ 0ᵀ  −eᵀ   0ᵀ  eᵀ ]
//
// In the sparse form ("Computing Jacobian") a world side has no block: the other body's block
// goes in Jsp[0] and Jmap[1] = −1. A static body (RigidBody::static_body) is an ordinary index.
// The rows are written with ζ = 0 and bounds (−∞, ∞); each constraint sets its own.
#pragma once

#include <vector>

#include "constraints/constraint_row.h"
#include "motion/rigid_body.h"

namespace lamina {

// The body index that stands for the fixed world (Jmap's −1).
inline constexpr int world = -1;

struct Anchor {
  int body = world;             // index into the bodies, or world
  Vec3 local = Vec3::Zero();    // r0: body-frame offset from x, in m; the world point for world
};

// The anchor at world point p of body b now: r0 = Rᵀ (p − x) (eq. 1-25 inverted), or p itself.
// Throws std::out_of_range for a body index past the bodies.
Anchor anchor_at(const std::vector<RigidBody>& bodies, int body, const Vec3& world_point);

// p, the anchor's world position now (eq. 1-25).
Vec3 anchor_position(const std::vector<RigidBody>& bodies, const Anchor& anchor);

// The orientation of body b, or the identity for the world.
Quat orientation_of(const std::vector<RigidBody>& bodies, int body);

// The row of Ċ = u · (ṗ_b − ṗ_a) for a world direction u.
ConstraintRow point_row(const std::vector<RigidBody>& bodies, const Anchor& a, const Anchor& b,
                        const Vec3& u);

// The row of Ċ = e · (ω_b − ω_a) for a world axis e.
ConstraintRow angular_row(int body_a, int body_b, const Vec3& e);

}  // namespace lamina
