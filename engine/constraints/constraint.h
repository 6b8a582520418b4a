// A constraint: something that writes Jacobian rows for the bodies' state at t (chapter 3).
//
//   C        the position error, 0 when the constraint holds (eq. 3-1, 3-6, 3-13: ε)
//   J        Ċ = J V (eq. 3-7, 3-8)
//   ζ        the velocity the row asks for: J V(t+Δt) = ζ (eq. 3-15)
//   β        the fraction of C removed per step, 0 ≤ β ≤ 1 (eq. 3-14)
//
// Bias. The text writes eq. 3-14 as v(t+Δt)·N = −β ε and says β = 0 keeps the error while
// β = 1 corrects it at once. With x(t+Δt) = x + v(t+Δt) Δt (eq. 2-5) the error after the step
// is C + Δt ζ, so "at once" needs ζ = −C/Δt: the text's ε is a length where a velocity belongs,
// and its β carries a hidden 1/Δt. Lamina writes the Δt out:
//   equality   ζ = −β C / Δt                  → C(t+Δt) = (1 − β) C for a linear C
//   inequality C ≥ 0 (eq. 3-17): for C > 0 the gap may close within the step but no further,
//              ζ = −C / Δt (eq. 3-18 with eq. 2-5); for C ≤ 0, ζ = −β C / Δt as above.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "constraints/constraint_row.h"
#include "constraints/jacobian_rows.h"
#include "motion/rigid_body.h"

namespace lamina {

class Constraint {
 public:
  virtual ~Constraint() = default;
  // Appends this constraint's rows (Jsp, Jmap, ζ, bounds) for the bodies' state at t, with
  // the step Δt (s) and the bias factor β. A constraint writes the same number of rows, on the
  // same bodies, every step, so that the solver can warm start from the last step's λ.
  virtual void write_rows(const std::vector<RigidBody>& bodies, double dt, double beta,
                          std::vector<ConstraintRow>& rows) const = 0;
  // What it is, in a few words: "revolute joint", "distance constraint", ...
  virtual const char* kind() const = 0;
  // The two bodies it joins, each an index into the bodies or world (−1).
  virtual std::array<int, 2> bodies() const = 0;
  // Its two ends, where it is drawn as a link with a pin at each end (a rod, a pin joint);
  // nothing for a constraint without ends (an angle limit, an incline).
  virtual std::optional<std::array<Anchor, 2>> ends() const { return std::nullopt; }
};

using ConstraintList = std::vector<std::unique_ptr<Constraint>>;

// ζ of an equality row (eq. 3-14, with the text's hidden 1/Δt written out): −β C / Δt.
double equality_bias(double C, double dt, double beta);

// ζ of a row C ≥ 0 (eq. 3-17..3-19): −C/Δt while C > 0, −β C / Δt once C ≤ 0.
double inequality_bias(double C, double dt, double beta);

// Checks the bodies of a two-body constraint: each an index ≥ 0 or world (−1), not the same
// body twice, not both the world.
void require_body_pair(int body_a, int body_b, const std::string& what);

// Every constraint's rows, in list order.
std::vector<ConstraintRow> write_all_rows(const std::vector<RigidBody>& bodies,
                                          const ConstraintList& constraints, double dt,
                                          double beta);

}  // namespace lamina
