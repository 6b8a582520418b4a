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

#include <vector>

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

// The same method with its memory kept from solve to solve: an LCP of the size solved last is
// solved again without allocating (a World's step solves its islands every step).
class LemkeSolver {
 public:
  // As solve_lcp_lemke; the solution is z() when solved.
  LemkeStatus solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, int max_pivots = 0);
  const Eigen::VectorXd& z() const { return z_; }  // the solution when solved, zeros otherwise
  int pivots() const { return pivots_; }           // pivots taken by the last solve

 private:
  // The tableau B⁻¹ [I  −M  −d | q] of the n rows: columns 0..n−1 are the w's, n..2n−1 the z's,
  // 2n is z0, and the last column is the basic variables' values.
  void start(const Eigen::MatrixXd& M, const Eigen::VectorXd& q);
  void pivot(int row, int variable);
  int leaving_row(int variable) const;
  bool lexicographically_less(int a, int b, int variable) const;
  void read_z();
  bool solves(const Eigen::MatrixXd& M, const Eigen::VectorXd& q);
  int z0() const { return 2 * n_; }
  double value(int row) const { return t_(row, 2 * n_ + 1); }
  int complement(int variable) const { return variable < n_ ? variable + n_ : variable - n_; }

  int n_ = 0;
  Eigen::MatrixXd t_;                 // the tableau
  Eigen::VectorXd factors_;           // a pivot's multiples of the pivot row, one per row
  std::vector<int> basis_;            // basis_[row]: the variable basic in that row
  std::vector<unsigned char> basic_;  // basic_[variable]: 1 when it is basic
  Eigen::VectorXd z_;                 // the solution
  Eigen::VectorXd w_, terms_;         // M z + q and Σ_j |M_ij z_j|, for checking z
  int pivots_ = 0;
};

}  // namespace lamina
