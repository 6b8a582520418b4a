// The rows a contact adds to the MLCP (chapter 4, eq. 4-1..4-5; chapter 5, eq. 5-4..5-11).
//
//   r1 = c − x1,  r2 = c − x2                       levers from the centres to the contact point
//   contact row   J = [−nᵀ  −(r1×n)ᵀ  nᵀ  (r2×n)ᵀ]  0 ≤ λ < ∞                       (eq. 4-3)
//   friction row  J = [−uᵀ  −(r1×u)ᵀ  uᵀ  (r2×u)ᵀ]  −μ λc ≤ λ ≤ μ λc               (chapter 4)
//   u1 = z × n (in the plane); u2 = z (the text's second tangent, optional: its λ is 0)
//   ζ/Δt = −β min(C + slop, 0) / Δt    the push-out of eq. 4-4, 4-5 (with a slop)
//   gap:  −C / Δt when C > 0            a cached point that opened a gap may close it (notes fix 6)
//   bounce: −e (J V) when J V < −v_e    restitution, beyond the text (Box2D's rule)
// ConstraintRow::zeta is the velocity J V(t+Δt) must reach (eq. 3-15), so the text's distance
// ζ of eq. 4-4 is stored divided by Δt, as eq. 4-5 uses it.
// A row with a static body keeps only the other body's block, as eq. 5-8 writes it.
#pragma once

#include <vector>

#include "constraints/constraint_row.h"
#include "contact/contact.h"
#include "motion/rigid_body.h"

namespace lamina {

// How penetration is corrected.
enum class PositionCorrection {
  baumgarte,     // the text: the push-out is in the velocity rows, so it stays in v
  split_impulse  // beyond the text: a second solve moves positions only, v keeps no push-out
};

struct ContactSettings {
  double beta = 0.2;                   // β of eq. 4-4: fraction of the penetration removed per step
  double slop = 0.005;                 // penetration left alone, in m (Box2D's b2_linearSlop)
  double restitution_threshold = 1.0;  // v_e: slower approaches do not bounce, in m/s (Box2D's)
  PositionCorrection correction = PositionCorrection::split_impulse;  // see above
  bool out_of_plane_friction = false;  // add the u2 = z friction row too
};

// What a row of the velocity MLCP stands for.
enum class RowKind {
  contact,                // a contact row, eq. 4-3 (0 ≤ λ)
  friction,               // the friction row along u1 = z × n (|λ| ≤ μ λc)
  out_of_plane_friction,  // the text's second tangent u2 = z (its λ is 0 in the plane)
  joint                   // a joint's row (engine/constraints)
};

// Friction rows per contact of a pair: none when μ = 0 (their bounds would be ±0), u1, and u2
// when asked for.
int friction_rows_per_contact(const ContactPair& pair, const ContactSettings& settings);

// Appends the rows of every pair, from the first row of `rows` on: the pair's contact rows,
// then its friction rows (below their contact rows, as the text orders them, so a friction
// bound reads the λc updated in the same sweep), with their warm start λ from the cache and
// their kinds.
void add_contact_rows(const std::vector<ContactPair>& pairs, const std::vector<RigidBody>& bodies,
                      const ContactSettings& settings, double dt, std::vector<ConstraintRow>& rows,
                      std::vector<double>& warm_start, std::vector<RowKind>& kinds);

// Stores the solved λ of the rows add_contact_rows appended (from row 0) into the cache.
void store_contact_lambdas(std::vector<ContactPair>& pairs, const std::vector<double>& lambda,
                           const ContactSettings& settings);

// Split impulse: for each contact, the index of its contact row among the rows add_contact_rows
// appended (from row 0), and the ζ the same row asks of the position solve: J V_p ≥ push-out
// (or gap). `rows` and `zeta` are overwritten.
void position_targets(const std::vector<ContactPair>& pairs, const ContactSettings& settings,
                      double dt, std::vector<int>& rows, std::vector<double>& zeta);

// Split impulse: the contact rows of add_contact_rows (in `velocity_rows` from row 0) again, one
// per contact, with the ζ of position_targets: the position MLCP's rows, appended to `rows`.
void add_position_rows(const std::vector<ContactPair>& pairs,
                       const std::vector<ConstraintRow>& velocity_rows,
                       const ContactSettings& settings, double dt,
                       std::vector<ConstraintRow>& rows);

// J V of a row at the bodies' current velocities (eq. 5-4, 5-5: the contact point's velocity along n).
double row_velocity(const ConstraintRow& row, const std::vector<RigidBody>& bodies);

}  // namespace lamina
