#include "constraints/jacobian_rows.h"

#include <cassert>

namespace lamina {
namespace {

// The arm r = p − x of an anchor: zero for the world, whose "velocity" is zero anyway.
Vec3 arm(const std::vector<RigidBody>& bodies, const Anchor& anchor) {
  assert(anchor.body >= world && anchor.body < static_cast<int>(bodies.size()));
  if (anchor.body == world) return Vec3::Zero();
  return bodies[anchor.body].rotation * anchor.local;
}

Vec6 block(const Vec3& linear, const Vec3& angular) {
  Vec6 j;
  j << linear, angular;
  return j;
}

// Places the two bodies' blocks in sparse form: a world side is left out, and a lone body's
// block goes first so that Jmap[1] = −1 marks a one-body row.
ConstraintRow sparse_row(int body_a, const Vec6& block_a, int body_b, const Vec6& block_b) {
  assert(body_a != world || body_b != world);
  ConstraintRow row;
  if (body_a == world) {
    row.Jsp = {block_b, Vec6::Zero()};
    row.Jmap = {body_b, world};
  } else if (body_b == world) {
    row.Jsp = {block_a, Vec6::Zero()};
    row.Jmap = {body_a, world};
  } else {
    row.Jsp = {block_a, block_b};
    row.Jmap = {body_a, body_b};
  }
  return row;
}

}  // namespace

Anchor anchor_at(const std::vector<RigidBody>& bodies, int body, const Vec3& world_point) {
  if (body == world) return {world, world_point};
  const RigidBody& b = bodies.at(body);
  return {body, b.rotation.transpose() * (world_point - b.x)};
}

Vec3 anchor_position(const std::vector<RigidBody>& bodies, const Anchor& anchor) {
  if (anchor.body == world) return anchor.local;
  // eq. 1-25: p = x + R r0
  return bodies[anchor.body].x + arm(bodies, anchor);
}

Quat orientation_of(const std::vector<RigidBody>& bodies, int body) {
  assert(body >= world && body < static_cast<int>(bodies.size()));
  return body == world ? Quat::Identity() : bodies[body].q;
}

ConstraintRow point_row(const std::vector<RigidBody>& bodies, const Anchor& a, const Anchor& b,
                        const Vec3& u) {
  // J = [ −uᵀ  −(r_a × u)ᵀ   uᵀ  (r_b × u)ᵀ ]
  return sparse_row(a.body, block(-u, -arm(bodies, a).cross(u)), b.body,
                    block(u, arm(bodies, b).cross(u)));
}

ConstraintRow angular_row(int body_a, int body_b, const Vec3& e) {
  // J = [ 0ᵀ  −eᵀ   0ᵀ  eᵀ ]
  return sparse_row(body_a, block(Vec3::Zero(), -e), body_b, block(Vec3::Zero(), e));
}

}  // namespace lamina
