// A contact point kept from step to step, and the pair of bodies it belongs to
// (chapter 4 "Contact caching", Fig 4-2..4-5; chapter 5, eq. 5-12).
//
//   p_k = x_k + R_k r_k     the contact's point on body k, re-placed from its anchor (eq. 5-12)
//   r_k = R_kᵀ (p_k − x_k)  the anchor, stored when the point is found (eq. 5-12)
//   C   = (p2 − p1) · n     the separation of eq. 4-1 (< 0: penetrating)
//   c   = (p1 + p2) / 2     the contact point where the rows' levers r1 = c − x1, r2 = c − x2 end
// n is stored in the frame of its reference body (the one whose surface it is normal to), so
// it turns with that body, as the text's n1 does (the ω1 × n1 term of eq. 4-2).
#pragma once

#include <array>
#include <cstdint>

#include "constraints/constraint_row.h"
#include "contact/broad_phase.h"
#include "contact/narrow_phase.h"

namespace lamina {

// Where a contact point of a step comes from (Fig 4-2..4-5):
enum class ContactOrigin : std::int8_t {
  fresh,    // new: this step's deepest point (Fig 4-2), no λ from before: a cold start
  refound,  // this step's deepest point found where a cached point was: it takes that point's
            // place and its λ (the warm start)
  kept      // a cached point re-placed from its anchors (eq. 5-12), not found this step
};

// "new", "refound", "kept": how traces and explanations name an origin.
const char* origin_name(ContactOrigin origin);

struct Contact {
  std::array<Vec2, 2> anchor{Vec2::Zero(), Vec2::Zero()};  // r_k on each body's surface, body k's frame, in m (eq. 5-12)
  Vec2 local_normal = Vec2::UnitY();  // n in the reference body's frame, unit, body 1 → body 2
  double lambda_normal = 0.0;         // λ of the contact row at the last solve, in N (warm start)
  double lambda_tangent = 0.0;        // λ of the friction row along u1 at the last solve, in N

  // Measured every step, from the narrow phase or from the anchors:
  Vec2 point = Vec2::Zero();          // c, midway between the two surface points, world, in m
  Vec2 normal = Vec2::UnitY();        // n, world, unit, body 1 → body 2
  double separation = 0.0;            // C of eq. 4-1, in m; −depth when penetrating
  double drift_squared = 0.0;         // |(p2 − p1) − C n|², the anchors' slide apart, in m²
  ContactOrigin origin = ContactOrigin::fresh;  // how this step got it (above)
  // Kept from step to step like the anchors, but here beside the small fields: a Contact fills
  // 128 bytes, two cache lines (144 with it up there: 1–2 % of a one-thread step at base 80).
  std::int8_t reference = 0;          // the body n is normal to: 0 (body 1) or 1 (body 2)

  // Where its rows sit in this step's MLCP, recorded when they are written (the row map):
  int row = -1;                              // its contact row (eq. 4-3)
  std::array<int, 2> friction_rows{-1, -1};  // its friction rows along u1 = z × n and u2 = z; −1: none

  // Found by this step's narrow phase (new or re-found); else re-placed from the cache (kept).
  bool fresh() const { return origin != ContactOrigin::kept; }
};

// Body 2's pose seen from body 1, which contact recycling compares from step to step
// (contact_cache.h): how far the pair moved relative to each other, whatever it moved in the world.
struct RelativePose {
  Vec2 offset = Vec2::Zero();  // R1ᵀ (x2 − x1), in m
  Vec2 turn = Vec2::UnitX();   // R1ᵀ R2 e_x: (cos, sin) of body 2's angle from body 1's
};

RelativePose relative_pose(const Pose2& pose1, const Pose2& pose2);

// The contacts of one pair of bodies: at most two in the plane (see ContactCache).
struct ContactPair {
  BodyPair bodies;                    // (body 1, body 2), body 1 < body 2
  double friction = 0.0;              // μ of the pair, √(μ1 μ2)
  double restitution = 0.0;           // e of the pair, max(e1, e2)
  int capacity = 2;                   // most contacts kept: 2, or 1 when a circle is in the pair
  int count = 0;                      // contacts in use
  std::array<Contact, 2> contacts{};  // the first `count` are in use
  // Contact recycling (contact_cache.h): where the narrow phase last found a point of the pair,
  // and whether that point was one the pair held already (re-found: nothing left to gain).
  RelativePose found_at;              // the bodies' relative pose then
  bool settled = false;               // its point was re-found
  bool recycled = false;              // this step: its points kept without the narrow phase
  RowRange rows;                      // its rows in this step's MLCP: contact rows, then friction rows
};

// A contact from the narrow phase's deepest point: the incident body's point is `point`, the
// reference body's is `depth` above it on the reference surface; both anchored (eq. 5-12).
Contact make_contact(const Collision& collision, const Pose2& pose1, const Pose2& pose2);

// Re-places a contact from its anchors at the bodies' current poses and re-measures it:
// point, normal, separation (eq. 4-1) and drift (squared: compared, never shown).
void place(Contact& contact, const Pose2& pose1, const Pose2& pose2);

// The point c = (p1 + p2)/2 of a contact re-placed from its anchors (eq. 5-12), without the
// rest of place's measuring.
Vec2 placed_point(const Contact& contact, const Pose2& pose1, const Pose2& pose2);

// Moves the reference body's anchor under the incident body's point, so the drift is zero and
// the separation unchanged: a sliding contact is re-anchored, not dropped, since dropping can
// lose both points of a pair in one step and only one comes back per step.
void reanchor(Contact& contact, const Pose2& pose1, const Pose2& pose2);

// The reference body's point of a contact, world frame.
Vec2 reference_point(const Contact& contact, const Pose2& pose1, const Pose2& pose2);

}  // namespace lamina
