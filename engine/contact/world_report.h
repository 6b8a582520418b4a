// What one World::step solved, for the tutorials' step-through output and for tests.
// Filled only when a report is asked for; the ordinary step records nothing.
//
//   contacts   every contact point solved: where, which way, fresh or cached, its λ
//   velocity   the MLCP of eq. 3-16: rows (J, ζ, bounds, body indices), η, d, λ_exp, λ,
//              the residual after every PGS sweep, and W = J B λ − η (eq. 3-23)
//   position   split impulse only: the position MLCP (ζ = push-out, no V or F_ext terms)
#pragma once

#include <vector>

#include "constraints/step_report.h"
#include "contact/contact_rows.h"

namespace lamina {

// One contact point as solved, in world terms (for rendering and reports).
struct ContactInfo {
  BodyPair bodies;              // (body 1, body 2), indices into World::bodies()
  Vec3 point = Vec3::Zero();    // c, world frame, in m
  Vec3 normal = Vec3::UnitY();  // n, unit, from body 1 to body 2
  double separation = 0.0;      // C of eq. 4-1, in m (negative: penetrating)
  bool cached = false;          // re-placed from the cache (false: this step's deepest point)
  double lambda_normal = 0.0;   // λ of its contact row, in N (impulse λ Δt)
  double lambda_tangent = 0.0;  // λ of its friction row along u1, in N
};

struct WorldReport {
  double time = 0.0;                 // t at the start of the step, in s
  std::vector<ContactInfo> contacts; // in row order: contact k owns the rows of its kind below
  std::vector<RowKind> kinds;        // what each velocity row stands for
  StepReport velocity;               // the velocity MLCP, eq. 3-16, and its PGS solution
  StepReport position;               // the split-impulse position MLCP (empty for Baumgarte)
};

// The constraint force and torque F_c = J_bᵀ λ on body b of a solved MLCP (eq. 3-11, 5-9):
// [f_c; τ_c], the torque about the body's centre, in N and N·m.
Vec6 constraint_wrench(const StepReport& report, int body);

// The contacts of the cache's pairs, in row order.
std::vector<ContactInfo> contact_infos(const std::vector<ContactPair>& pairs);

}  // namespace lamina
