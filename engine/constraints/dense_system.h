// The dense reference path for small systems: the matrices of chapter 3 written out in full.
//
//   V      6n × 1   [v1 ω1 … vn ωn]                      (eq. 3-5)
//   F_ext  6n × 1   [f1 τ1 … fn τn]                      (eq. 3-9)
//   J      s × 6n   row i holds Jsp[i][k] in columns 6·Jmap[i][k] .. +5   (eq. 3-8)
//   M⁻¹    6n × 6n  diag(m1⁻¹ E, I1⁻¹, …, mn⁻¹ E, In⁻¹)   (eq. 3-12)
//   Bᵀ     s × 6n   J M⁻¹, the text's Convert             (eq. 3-16)
//   J B    s × s    J M⁻¹ Jᵀ                              (eq. 3-16)
//   η      s × 1    ζ/Δt − J (V/Δt + M⁻¹ F_ext)           (eq. 3-16)
//
// The solver never builds these (they are mostly zeros, see "Computing Jacobian"). Two kinds of
// function make them:
//   - views of the one assembled MLCP (mlcp.h), for explanations: dense_jacobian(mlcp),
//     dense_b_transpose(mlcp);
//   - build_dense_system, from the written rows by matrix products alone, sharing none of the
//     MLCP's assembly: the independent reference the tests check that assembly against.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "constraints/constraint_row.h"
#include "constraints/mlcp.h"
#include "motion/rigid_body.h"

namespace lamina {

struct DenseSystem {
  Eigen::MatrixXd J;             // s × 6n Jacobian; row units 1 (linear part) or m (angular part)
  Eigen::MatrixXd inverse_mass;  // M⁻¹, 6n × 6n, in 1/kg and 1/(kg·m²)
  Eigen::MatrixXd JB;            // J M⁻¹ Jᵀ, s × s: the A of Gauss-Seidel
  Eigen::VectorXd zeta;          // ζ, s × 1, in m/s or rad/s
  Eigen::VectorXd eta;           // η, s × 1, in m/s² or rad/s²
};

// eq. 3-5: V, the bodies' [v ω] stacked.
Eigen::VectorXd stacked_velocity(const std::vector<RigidBody>& bodies);

// eq. 3-9: F_ext, the bodies' accumulated [F τ] stacked.
Eigen::VectorXd stacked_external_force(const std::vector<RigidBody>& bodies);

// eq. 3-12: M⁻¹ = diag(m⁻¹ E, I⁻¹) per body, zero blocks for a static body.
Eigen::MatrixXd dense_inverse_mass(const std::vector<RigidBody>& bodies);

// eq. 3-8: the full s × 6n Jacobian of the sparse rows.
Eigen::MatrixXd dense_jacobian(const std::vector<ConstraintRow>& rows, int body_count);

// J (s × 6n) and Bᵀ = J M⁻¹ (s × 6n, the text's Convert) of an assembled MLCP, from its
// sparse Jsp and Bsp.
Eigen::MatrixXd dense_jacobian(const Mlcp& mlcp);
Eigen::MatrixXd dense_b_transpose(const Mlcp& mlcp);

// J, M⁻¹, J M⁻¹ Jᵀ, ζ and η of the rows for the bodies' current state and accumulated forces.
DenseSystem build_dense_system(const std::vector<RigidBody>& bodies,
                               const std::vector<ConstraintRow>& rows, double dt);

}  // namespace lamina
