// The mixed linear complementarity problem of one step (eq. 3-16, 3-23, 3-24):
//   J B λ = η  with  B = M⁻¹ Jᵀ,  η = ζ/Δt − J (V/Δt + M⁻¹ F_ext),  λ⁻ ≤ λ ≤ λ⁺.
// Functions reading λ take an Eigen::Ref, so that λ kept in a std::vector (a World keeps its
// memory from step to step) is read through an Eigen::Map without a copy.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "constraints/constraint_row.h"
#include "constraints/row_terms.h"
#include "motion/rigid_body.h"

namespace lamina {

struct Mlcp {
  std::vector<ConstraintRow> rows;       // J in sparse form with ζ and the bounds
  std::vector<std::array<Vec6, 2>> Bsp;  // Bᵀ in the same sparse form: M⁻¹ of each block (Convert)
  Eigen::VectorXd eta;                   // η, in m/s² or rad/s² (eq. 3-16)
  Eigen::VectorXd d;                     // d_i = J_i · B_i, the diagonal of J B
  int body_count = 0;                    // n, the number of bodies V spans
};

// Body b's 6-vector [v; ω] (eq. 3-5) and [F; τ] of the forces accumulated on it (eq. 3-9).
Vec6 velocity_of(const RigidBody& body);
Vec6 external_force_of(const RigidBody& body);

// V/Δt + M⁻¹ F_ext of every body (eq. 3-16): the velocity each body would reach without
// constraints, per Δt, in m/s² or rad/s². `out` is resized to the bodies (its memory is reused).
void unconstrained_velocities(const std::vector<RigidBody>& bodies, double dt,
                              std::vector<Vec6>& out);

// Builds the MLCP of eq. 3-16 from the rows, the bodies' velocities and accumulated forces.
Mlcp assemble_mlcp(const std::vector<RigidBody>& bodies, std::vector<ConstraintRow> rows,
                   double dt);
// The same for given V/Δt + M⁻¹ F_ext (see unconstrained_velocities; zeros: η = ζ/Δt).
Mlcp assemble_mlcp(const std::vector<RigidBody>& bodies, std::vector<ConstraintRow> rows,
                   const std::vector<Vec6>& unconstrained, double dt);

// J_i · X for per-body 6-vectors X (the text's Multiply, one row; guards Jmap[1] = −1), each
// block's dot product summed in order (ordered_dot).
double row_times(const ConstraintRow& row, const std::vector<Vec6>& per_body);

// a = B λ, one 6-vector per body: the text's TransposeMultiply, scaled by λ[i] as it must be
// (the text's pseudo-code writes λ[b1] and λ[b2]).
std::vector<Vec6> transpose_multiply(const Mlcp& mlcp,
                                     const Eigen::Ref<const Eigen::VectorXd>& lambda);

// W = J B λ − η (eq. 3-23) for a given λ.
Eigen::VectorXd complementarity_slack(const Mlcp& mlcp,
                                      const Eigen::Ref<const Eigen::VectorXd>& lambda);

// The bounds of a row for the current λ (λ[0..s)): fixed, or ±μ λc for a friction row (eq. 3-26).
// `Row` is a ConstraintRow or any row with its lambda_min, lambda_max, friction_of and mu.
template <class Row>
std::array<double, 2> bounds_of(const Row& row, const double* lambda) {
  if (row.friction_of < 0) return {row.lambda_min, row.lambda_max};
  // eq. 3-26: a friction row is bounded by ±μ λc of its contact row
  const double limit = row.mu * lambda[row.friction_of];
  return {-limit, limit};
}

// The bounds of row i for the current λ: fixed, or ±μ λc for a friction row (eq. 3-26).
std::array<double, 2> row_bounds(const ConstraintRow& row,
                                 const Eigen::Ref<const Eigen::VectorXd>& lambda);

// How far λ is from solving the MLCP: per row |W_i| when λ is inside its bounds, and only the
// wrong-signed part of W_i at a bound (eq. 3-24); the Euclidean norm over rows.
double mlcp_residual(const Mlcp& mlcp, const Eigen::Ref<const Eigen::VectorXd>& lambda);

// F_c = Jᵀ λ (eq. 3-11), added to each body's accumulated force and torque.
void apply_constraint_forces(std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                             const Eigen::Ref<const Eigen::VectorXd>& lambda);

}  // namespace lamina
