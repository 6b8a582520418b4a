// The two kinds of Jacobian row every constraint and contact is built from, and the one rule
// for which bodies a row holds a block for.
//
//   lever        r = p − x, from a body's centre to the point p the row acts at
//   anchor       a point fixed in body b, r0 in b's frame: p = x_b + R_b r0 (eq. 1-25);
//                or a fixed point of the world (b = world): p = r0
//   point row    Ċ = u · (ṗ_b − ṗ_a) = u·(v_b + ω_b × r_b) − u·(v_a + ω_a × r_a)   (eq. 1-30)
//                J = [ −uᵀ  −(r_a × u)ᵀ   uᵀ  (r_b × u)ᵀ ]   (u·(ω × r) = ω·(r × u); eq. 4-3, 5-8)
//   angular row  Ċ = e · (ω_b − ω_a),   J = [ 0ᵀ  −eᵀ   0ᵀ  eᵀ ]
//
// Static bodies. A static body never moves and its M⁻¹ is zero (eq. 5-1): its share of J V is
// zero and so is its block of B = M⁻¹ Jᵀ. It enters a row as the fixed world does, with no
// block, the way eq. 5-8 writes the ground's columns of J (0ᵀ, 0ᵀ). In the sparse form
// ("Computing Jacobian") a lone moving body's block goes in Jsp[0] and Jmap[1] = −1 marks the
// one-body row. Contacts and joints follow this one rule; every row moves at least one body.
// Rows are written with ζ = 0 and bounds (−∞, ∞); each constraint sets its own.
#pragma once

#include <array>
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

// Whether body b holds a block in the rows it is part of: a body that moves (not the world,
// not a static body).
bool holds_block(const std::vector<RigidBody>& bodies, int body);

// The ends of a row that hold a block, in Jmap order: the moving bodies among (a, b), each with
// the sign of its blocks (−1 for a, +1 for b) and its lever r.
struct RowEnds {
  int count = 0;                          // 1 or 2
  std::array<int, 2> body{world, world};  // Jmap
  std::array<double, 2> sign{};           // −1 for body a, +1 for body b
  std::array<Vec3, 2> lever;              // r = p − x of each, in m
};

// The ends of a row acting at one world point p on bodies a and b (a contact): r = p − x.
RowEnds ends_at_point(const std::vector<RigidBody>& bodies, int body_a, int body_b,
                      const Vec3& point);
// The ends of a row between two anchors (a joint): r = R r0 of each.
RowEnds ends_at_anchors(const std::vector<RigidBody>& bodies, const Anchor& a, const Anchor& b);

// Writes the point row along the world direction u into `row` (Jsp, Jmap); ζ and the bounds
// are left as they are.
void write_point_row(const RowEnds& ends, const Vec3& u, ConstraintRow& row);

// The point row of Ċ = u · (ṗ_b − ṗ_a) between two anchors.
ConstraintRow point_row(const std::vector<RigidBody>& bodies, const Anchor& a, const Anchor& b,
                        const Vec3& u);

// The angular row of Ċ = e · (ω_b − ω_a) for a world axis e.
ConstraintRow angular_row(const std::vector<RigidBody>& bodies, int body_a, int body_b,
                          const Vec3& e);

}  // namespace lamina
