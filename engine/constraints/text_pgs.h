// The text's Projected Gauss-Seidel, line by line (chapter 3, "Computing Jacobian" and
// "Projected Gauss-Seidel Method"), over the text's own sparse arrays:
//
//   Jsp[s][2]   row i's two non-zero 1 × 6 blocks of J (eq. 3-8), each [v ω]
//   Jmap[s][2]  their bodies; Jmap[i][1] = −1 for a one-body row
//   M⁻¹[n]      each body's 6 × 6 block of M⁻¹ = diag(m⁻¹E, I⁻¹) (eq. 3-12)
//   Bsp[s][2]   Convert(Jsp, Jmap, M⁻¹): row i's blocks of Bᵀ = J M⁻¹, B = M⁻¹ Jᵀ (eq. 3-16)
//   a[n]        TransposeMultiply(Bsp, Jmap, λ): a = B λ, one 6-vector per body
//   d[s]        d_i = Jsp[i][0]·Bsp[i][0] + Jsp[i][1]·Bsp[i][1], the diagonal of J B
//   the sweep   Delta = (η_i − Jsp[i][0]·a[b1] − Jsp[i][1]·a[b2]) / d_i
//               λ_i ← max(λ⁻_i, min(λ_i + Delta, λ⁺_i)),  a ← a + (λ_i new − old) Bsp[i]
//
// This is a second, plain solver kept beside the engine's: PgsSolver (pgs_solver.h) sweeps the
// same MLCP packed for speed (mlcp.h, packed_rows.h), and shares no code with this file beyond
// ConstraintRow and RigidBody. The tests check one against the other; the chapter-3 tutorial
// prints this one's arrays. The text's three slips are mended where they occur, each marked at
// its line: TransposeMultiply scales by λ[i] (the text writes λ[b1], λ[b2]), and Convert,
// TransposeMultiply and the sweep skip a second body b2 = −1 (the text guards only Multiply).
#pragma once

#include <array>
#include <vector>

#include "constraints/constraint_row.h"
#include "motion/rigid_body.h"

namespace lamina::text {

using Vector6 = Vec6;                           // the text's Vector6: a [v ω] or [f τ] block
using Matrix6x6 = Eigen::Matrix<double, 6, 6>;  // the text's Matrix6x6: one body's M⁻¹
using Blocks = std::vector<std::array<Vector6, 2>>;  // Jsp[s][2] or Bsp[s][2]
using BodyMap = std::vector<std::array<int, 2>>;     // Jmap[s][2]

// The arguments of the text's ProjectedGaussSeidel, and chapter 4's friction rows.
struct Problem {
  Blocks Jsp;                        // Jsp[s][2], the rows' J blocks
  BodyMap Jmap;                      // Jmap[s][2], their bodies (−1: none)
  std::vector<Matrix6x6> M_inverse;  // M⁻¹[n], in 1/kg and 1/(kg·m²); zero for a static body
  std::vector<double> eta;           // η[s], in m/s² or rad/s² (eq. 3-16)
  std::vector<double> lambda_min;    // λ⁻[s], in N (eq. 3-24); a friction row's is set in the sweep
  std::vector<double> lambda_max;    // λ⁺[s], in N
  std::vector<int> friction_of;      // for a friction row the contact row of its λc, else −1
  std::vector<double> mu;            // μ of a friction row
};

// The text's arrays for the rows written at t and the bodies at t, their forces accumulated
// (F_ext): Jsp, Jmap and the bounds copied from the rows, M⁻¹ from each body, and
// η = ζ/Δt − Multiply(Jsp, Jmap, V/Δt + M⁻¹ F_ext) (eq. 3-16).
Problem make_problem(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                     double dt);

// Bᵀ = J M⁻¹, block by block: Bsp[i][k] = M⁻¹[Jmap[i][k]] Jsp[i][k] (M⁻¹ is symmetric).
Blocks Convert(const Blocks& Jsp, const BodyMap& Jmap, const std::vector<Matrix6x6>& M_inverse);

// J V for per-body 6-vectors V: Result[i] = Jsp[i][0]·V[b1] + Jsp[i][1]·V[b2].
std::vector<double> Multiply(const Blocks& Jsp, const BodyMap& Jmap, const std::vector<Vector6>& V);

// a = B λ for n bodies: each row adds λ[i] Bsp[i][k] to its bodies' a.
std::vector<Vector6> TransposeMultiply(const Blocks& Bsp, const BodyMap& Jmap,
                                       const std::vector<double>& lambda, int n);

// What ProjectedGaussSeidel computed on its way, for explanations and tests.
struct Trace {
  Blocks Bsp;                                       // Convert's Bsp[s][2]
  std::vector<double> d;                            // d[s], in 1/kg or 1/(kg·m²)
  std::vector<Vector6> a_start;                     // a = B λ_exp, per body, before the sweeps
  std::vector<std::vector<double>> lambda_after_sweep;  // λ[s] after each sweep, in N
  std::vector<Vector6> a;                           // a = B λ after the last sweep
};

// The text's ProjectedGaussSeidel: MAX_ITERATION sweeps from λ_exp; returns λ. With `trace`,
// fills it.
std::vector<double> ProjectedGaussSeidel(const Problem& problem, const std::vector<double>& lambda_exp,
                                         int max_iteration, Trace* trace = nullptr);

}  // namespace lamina::text
