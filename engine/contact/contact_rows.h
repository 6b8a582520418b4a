// The rows a contact adds to the MLCP (chapter 4, eq. 4-1..4-5; chapter 5, eq. 5-4..5-11).
//
//   r1 = c − x1,  r2 = c − x2                       levers from the centres to the contact point
//   contact row   J = [−nᵀ  −(r1×n)ᵀ  nᵀ  (r2×n)ᵀ]  0 ≤ λ < ∞                       (eq. 4-3)
//   friction row  J = [−uᵀ  −(r1×u)ᵀ  uᵀ  (r2×u)ᵀ]  −μ λc ≤ λ ≤ μ λc               (chapter 4)
//   u1 = z × n (in the plane); u2 = z (the text's second tangent, optional: its λ is 0)
//   ζ/Δt = −β min(C + slop, 0) / Δt    the push-out of eq. 4-4, 4-5 (with a slop; the text's
//                                       slop is 0)
// Beyond the text, each switched in ContactSettings (the text's method, solvers.h, has them off):
//   gap:  −C / Δt when C > 0            a cached point that opened a gap may close it within
//                                       the step, no faster (the text's ζ = 0 there makes boxes
//                                       hover and stacks creep)
//   bounce: −e (J V) when J V < −v_e    restitution (Box2D's rule)
//   one friction row per manifold       for a pair touching at two points, one row along u at
//                                       their middle, bounded by ±μ (λc1 + λc2). In the plane
//                                       the two points' friction rows differ only by
//                                       ((r_a − r_b)·n) in their ω_z entry, zero on a flat
//                                       manifold: PGS can then move λ from one to the other
//                                       freely and a resting box holds friction against
//                                       itself. One row carries the same total force with no
//                                       such freedom, and obeys Coulomb's law for the pair.
// ConstraintRow::zeta is the velocity J V(t+Δt) must reach (eq. 3-15), so the text's distance
// ζ of eq. 4-4 is stored divided by Δt, as eq. 4-5 uses it. The rows are point rows
// (jacobian_rows.h): a static body holds no block, as eq. 5-8 writes it.
#pragma once

#include <vector>

#include "constraints/constraint_row.h"
#include "constraints/mlcp.h"
#include "constraints/step_settings.h"
#include "contact/contact.h"
#include "motion/rigid_body.h"
#include "parallel/workers.h"

namespace lamina {

// How penetration is corrected.
enum class PositionCorrection {
  baumgarte,     // the text: the push-out is in the velocity rows, so it stays in v
  split_impulse  // beyond the text: a second solve moves positions only, v keeps no push-out
};

// Friction rows of a pair that touches at two points.
enum class FrictionRows {
  per_point,    // the text: one row per contact point, each bounded by its own ±μ λc
  per_manifold  // beyond the text: one row at the manifold's middle, ±μ (λc1 + λc2)
};

struct ContactSettings {
  double slop = 0.005;                 // penetration left alone, in m (Box2D's b2_linearSlop)
  double restitution_threshold = 1.0;  // v_e: slower approaches do not bounce, in m/s (Box2D's)
  PositionCorrection correction = PositionCorrection::split_impulse;  // see above
  bool restitution = true;             // honour the materials' e (false: e = 0, the text)
  bool close_gaps = true;              // a cached point's gap may close within a step
  FrictionRows friction = FrictionRows::per_manifold;  // see above
  bool out_of_plane_friction = false;  // add the u2 = z friction row too
};

// Throws std::invalid_argument naming the first setting out of range.
void validate(const ContactSettings& settings);

// The rows of every pair, written into a RowSink in runs (a RowWriter: Mlcp::assemble packs
// them as they come, and a step's contact rows are never stored as ConstraintRows), and each
// row's warm-start λ (the cache's) into `lambda`, which begin() sizes for all the rows: each
// pair's contact rows, then its friction rows (below their contact rows, as the text orders
// them, so a friction bound reads the λc updated in the same sweep). Records where they went:
// each pair's `rows`, each contact's `row` and `friction_rows` (both contacts of a manifold name
// its one friction row). Uses β and Δt. Run t of `runs` writes the rows of a run of the pairs
// (share_of: each pair's rows are its own).
class ContactRows final : public RowWriter {
 public:
  ContactRows(std::vector<ContactPair>& pairs, const std::vector<RigidBody>& bodies,
              const ContactSettings& settings, const StepSettings& step,
              std::vector<double>& lambda);
  std::size_t count(int t, int runs) override;
  void begin(std::size_t total) override;
  void write(int t, int runs, RowSink& sink) override;

 private:
  std::vector<ContactPair>& pairs_;
  const std::vector<RigidBody>& bodies_;
  ContactSettings settings_;  // copies: a writer made from temporaries keeps them
  StepSettings step_;
  std::vector<double>& lambda_;
};

// The same rows as ConstraintRows: makes `rows` the rows of every pair and `lambda` their
// warm-start λ, whatever they held before (their memory is reused). With `workers`, each of
// their threads writes the rows of a run of the pairs, in the same places.
void add_contact_rows(std::vector<ContactPair>& pairs, const std::vector<RigidBody>& bodies,
                      const ContactSettings& settings, const StepSettings& step,
                      std::vector<ConstraintRow>& rows, std::vector<double>& lambda,
                      Workers* workers = nullptr);

// Stores the solved λ of each contact's rows into the cache (the next step's warm start); a
// manifold's one friction λ is shared by its points in proportion to their λc, so that each
// point's share lies within its own ±μ λc and the two add up to the row's λ. With `workers`,
// each of their threads stores a run of the pairs (each pair's λ are its own).
void store_contact_lambdas(std::vector<ContactPair>& pairs, const double* lambda,
                           Workers* workers = nullptr);

// Split impulse: each contact's contact row, and the ζ the same row asks of the position solve,
// J V_p ≥ push-out (or gap), in the order of the pairs and their contacts. `rows` and `zeta`
// are overwritten. With `workers`, each of their threads writes a run of the pairs' targets, in
// the same places.
void position_targets(const std::vector<ContactPair>& pairs, const ContactSettings& settings,
                      const StepSettings& step, std::vector<int>& rows, std::vector<double>& zeta,
                      Workers* workers = nullptr);

}  // namespace lamina
