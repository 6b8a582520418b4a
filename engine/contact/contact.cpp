#include "contact/contact.h"

namespace lamina {

// Two cache lines, as contact.h lays it out (the merge and the rows copy and read every pair).
static_assert(sizeof(Contact) <= 128, "a Contact outgrew two cache lines");

const char* origin_name(ContactOrigin origin) {
  switch (origin) {
    case ContactOrigin::fresh:
      return "new";
    case ContactOrigin::refound:
      return "refound";
    case ContactOrigin::kept:
      return "kept";
  }
  return "new";
}
namespace {

const Pose2& pose_of(int k, const Pose2& pose1, const Pose2& pose2) { return k == 0 ? pose1 : pose2; }

}  // namespace

RelativePose relative_pose(const Pose2& pose1, const Pose2& pose2) {
  return {pose1.to_body(pose2.x), pose1.R.transpose() * pose2.R.col(0)};
}

Contact make_contact(const Collision& collision, const Pose2& pose1, const Pose2& pose2) {
  Contact contact;
  const int ref = collision.reference;
  // The reference body's outward normal: n itself for body 1, −n for body 2.
  const Vec2 outward = ref == 0 ? collision.normal : Vec2(-collision.normal);
  std::array<Vec2, 2> p;
  p[1 - ref] = collision.point;
  p[ref] = collision.point + collision.depth * outward;
  for (int k = 0; k < 2; ++k) {
    // eq. 5-12: r_a = R1ᵀ (x_a − x1)
    contact.anchor[k] = pose_of(k, pose1, pose2).to_body(p[k]);
  }
  contact.local_normal = pose_of(ref, pose1, pose2).R.transpose() * collision.normal;
  contact.reference = static_cast<std::int8_t>(ref);
  contact.origin = ContactOrigin::fresh;
  place(contact, pose1, pose2);
  return contact;
}

void place(Contact& contact, const Pose2& pose1, const Pose2& pose2) {
  // eq. 5-12: x_a(τ+Δt) = x1(τ+Δt) + R1(τ+Δt) r_a
  const Vec2 p1 = pose1.to_world(contact.anchor[0]);
  const Vec2 p2 = pose2.to_world(contact.anchor[1]);
  contact.normal = pose_of(contact.reference, pose1, pose2).R * contact.local_normal;
  // eq. 4-1: C = (x2 + r2 − x1 − r1) · n1
  contact.separation = (p2 - p1).dot(contact.normal);
  contact.drift_squared = ((p2 - p1) - contact.separation * contact.normal).squaredNorm();
  contact.point = 0.5 * (p1 + p2);
}

Vec2 placed_point(const Contact& contact, const Pose2& pose1, const Pose2& pose2) {
  // eq. 5-12 for both anchors, then their midpoint
  return 0.5 * (pose1.to_world(contact.anchor[0]) + pose2.to_world(contact.anchor[1]));
}

void reanchor(Contact& contact, const Pose2& pose1, const Pose2& pose2) {
  const int ref = contact.reference;
  const Vec2 p1 = pose1.to_world(contact.anchor[0]);
  const Vec2 p2 = pose2.to_world(contact.anchor[1]);
  // The reference point moves along the surface to face the incident point: p_ref = p_inc ∓ C n.
  const Vec2 moved = ref == 0 ? Vec2(p2 - contact.separation * contact.normal)
                              : Vec2(p1 + contact.separation * contact.normal);
  contact.anchor[ref] = pose_of(ref, pose1, pose2).to_body(moved);
  place(contact, pose1, pose2);
}

Vec2 reference_point(const Contact& contact, const Pose2& pose1, const Pose2& pose2) {
  return pose_of(contact.reference, pose1, pose2).to_world(contact.anchor[contact.reference]);
}

}  // namespace lamina
