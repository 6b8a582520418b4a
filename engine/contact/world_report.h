// What one World::step solved, for explanations, frames and tests. Filled only when a report is
// asked for; the ordinary step records nothing.
//
//   bodies     the bodies at t, before the step (the World holds them at t + Δt after it)
//   pairs      every contact pair solved: its points (where, which way, fresh or cached, λ) and
//              where its rows sit in the velocity MLCP (ContactPair::rows, Contact::row)
//   joints     where each joint's rows sit, in the order the joints were added
//   velocity   the MLCP of eq. 3-16 as assembled, λ_exp, λ and the residual after every sweep
//   position   split impulse only: the position MLCP (ζ = push-out, no V or F_ext terms)
// Row i of the velocity MLCP is a contact row, a friction row or a joint's row: the row map
// above says which, as the step recorded it.
#pragma once

#include <vector>

#include "constraints/constraint_row.h"
#include "constraints/step_report.h"
#include "contact/contact.h"

namespace lamina {

// One contact point as solved, in world terms (for rendering, traces and reports).
struct ContactInfo {
  BodyPair bodies;              // (body 1, body 2), indices into World::bodies()
  Vec3 point = Vec3::Zero();    // c, world frame, in m
  Vec3 normal = Vec3::UnitY();  // n, unit, from body 1 to body 2
  double separation = 0.0;      // C of eq. 4-1, in m (negative: penetrating)
  bool cached = false;          // re-placed from the cache (false: this step's deepest point)
  double lambda_normal = 0.0;   // λ of its contact row, a force in N (its impulse is λ Δt)
  double lambda_tangent = 0.0;  // λ of its friction row along u1, in N
  ContactOrigin origin = ContactOrigin::fresh;  // new, re-found or kept (cached ⇔ kept)
};

struct WorldReport {
  double time = 0.0;                // t at the start of the step, in s
  std::vector<RigidBody> bodies;    // the bodies at t
  std::vector<ContactPair> pairs;   // the contact pairs solved, with their rows
  std::vector<RowRange> joints;     // each joint's rows
  StepReport velocity;              // the velocity MLCP, eq. 3-16, and its PGS solution
  StepReport position;              // the split-impulse position MLCP (empty for Baumgarte)

  // The contact points solved, pair by pair, in row order.
  std::vector<ContactInfo> contacts() const;
};

// Contact k of a pair, in world terms.
ContactInfo contact_info(const ContactPair& pair, int k);
// The contact points of the pairs.
std::size_t contact_count(const std::vector<ContactPair>& pairs);
// The contacts of the pairs, in row order.
std::vector<ContactInfo> contact_infos(const std::vector<ContactPair>& pairs);

}  // namespace lamina
