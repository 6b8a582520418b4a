// Lemke's complementary pivoting: an exact solve of a linear complementarity problem (beyond the
// text, which solves its MLCP by Projected Gauss-Seidel only; its reference [3], Baraff 1994,
// solves contact forces by pivoting instead). Chapter 6 uses it as the ground truth PGS's λ is
// compared with.
//
//   find z ≥ 0 with w = M z + q ≥ 0 and zᵀ w = 0                    (the LCP (M, q))
//
// A contact MLCP without friction is one: z = λ, M = J B, q = −η (eq. 3-23, 3-24 with bounds
// [0, ∞)). Lemke's method adds an artificial variable z0 and a covering vector d = (1, …, 1):
//   w = M z + q + d z0,
// starts from z = 0, z0 = −min q (every w ≥ 0, one w = 0), and pivots: the variable that entered
// last leaves the basis's complement in, the ratio test picks who leaves, until z0 leaves (a
// solution) or a column has no positive entry (a ray: Lemke cannot tell, and says so). Ties in
// the ratio test are broken lexicographically, so a degenerate problem cannot cycle. For M
// positive semidefinite (J B is) Lemke finds a solution whenever one exists (Cottle, Pang and
// Stone, "The Linear Complementarity Problem", 1992, §4.4).
#pragma once

#include <Eigen/Core>

namespace lamina {

enum class LemkeStatus {
  solved,         // z0 left the basis: z solves the LCP
  ray,            // a ray termination: no solution was found (none exists for M PSD)
  out_of_pivots,  // max_pivots pivots without an end
  inaccurate      // z0 left, but the pivots' rounding left z or w = M z + q below zero, or
                  // z and w both positive in a row, beyond 1e-9 of that row's scale: the z
                  // found is no solution and is not returned (found by the physics fuzzer: a
                  // stack of frictionless overlapping boxes, λ = −0.06 N among forces of 0.7 N)
};

struct LemkeResult {
  LemkeStatus status = LemkeStatus::solved;
  Eigen::VectorXd z;  // the solution when solved (zeros otherwise)
  int pivots = 0;     // pivots taken
};

// Solves the LCP (M, q), M square, q of its size. max_pivots ≤ 0 means 50 · (n + 1).
// Throws std::invalid_argument for mismatched sizes or a non-finite entry.
LemkeResult solve_lcp_lemke(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, int max_pivots = 0);

}  // namespace lamina
