#include "constraints/jacobian_rows.h"

#include <cassert>

namespace lamina {
namespace {

// Adds body b, which holds a block, as the next end.
void add_end(int body, double sign, const Vec3& lever, RowEnds& ends) {
  ends.body[ends.count] = body;
  ends.sign[ends.count] = sign;
  ends.lever[ends.count++] = lever;
}

// The lever r = R r0 of an anchor: zero for the world, whose velocity is zero anyway.
Vec3 lever_of(const std::vector<RigidBody>& bodies, const Anchor& anchor) {
  assert(anchor.body >= world && anchor.body < static_cast<int>(bodies.size()));
  if (anchor.body == world) return Vec3::Zero();
  return bodies[anchor.body].rotation * anchor.local;
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
  return bodies[anchor.body].x + lever_of(bodies, anchor);
}

Quat orientation_of(const std::vector<RigidBody>& bodies, int body) {
  assert(body >= world && body < static_cast<int>(bodies.size()));
  return body == world ? Quat::Identity() : bodies[body].q;
}

bool holds_block(const std::vector<RigidBody>& bodies, int body) {
  assert(body >= world && body < static_cast<int>(bodies.size()));
  // eq. 5-1, 5-8: a fixed body has M⁻¹ = 0 and no velocity; its columns of J are left out
  return body != world && !bodies[body].is_static();
}

RowEnds ends_at_point(const std::vector<RigidBody>& bodies, int body_a, int body_b,
                      const Vec3& point) {
  RowEnds ends;
  if (holds_block(bodies, body_a)) add_end(body_a, -1.0, point - bodies[body_a].x, ends);
  if (holds_block(bodies, body_b)) add_end(body_b, 1.0, point - bodies[body_b].x, ends);
  assert(ends.count > 0);
  return ends;
}

RowEnds ends_at_anchors(const std::vector<RigidBody>& bodies, const Anchor& a, const Anchor& b) {
  RowEnds ends;
  if (holds_block(bodies, a.body)) add_end(a.body, -1.0, lever_of(bodies, a), ends);
  if (holds_block(bodies, b.body)) add_end(b.body, 1.0, lever_of(bodies, b), ends);
  assert(ends.count > 0);
  return ends;
}

void write_point_row(const RowEnds& ends, const Vec3& u, ConstraintRow& row) {
  for (int k = 0; k < ends.count; ++k) {
    // J = [ −uᵀ  −(r_a × u)ᵀ   uᵀ  (r_b × u)ᵀ ], one block per moving end
    row.Jsp[k].head<3>() = ends.sign[k] * u;
    row.Jsp[k].tail<3>() = ends.sign[k] * ends.lever[k].cross(u);
    row.Jmap[k] = ends.body[k];
  }
}

ConstraintRow point_row(const std::vector<RigidBody>& bodies, const Anchor& a, const Anchor& b,
                        const Vec3& u) {
  ConstraintRow row;
  write_point_row(ends_at_anchors(bodies, a, b), u, row);
  return row;
}

ConstraintRow angular_row(const std::vector<RigidBody>& bodies, int body_a, int body_b,
                          const Vec3& e) {
  // J = [ 0ᵀ  −eᵀ   0ᵀ  eᵀ ]: a point row without levers, acting on ω alone
  const RowEnds ends = ends_at_anchors(bodies, Anchor{body_a}, Anchor{body_b});
  ConstraintRow row;
  for (int k = 0; k < ends.count; ++k) {
    row.Jsp[k].head<3>().setZero();
    row.Jsp[k].tail<3>() = ends.sign[k] * e;
    row.Jmap[k] = ends.body[k];
  }
  return row;
}

}  // namespace lamina
