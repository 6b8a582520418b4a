// The step's MLCP (eq. 3-16, 3-23, 3-24, 3-26) solved exactly by Lemke's pivoting (lemke.h),
// friction included: beyond the text, the ground truth chapter 6 measures PGS's λ against.
//
// Each row's λ becomes non-negative LCP variables, so that the MLCP is one LCP (M, q):
//   a row with bounds [0, ∞) (a contact, a limit)   λ ≥ 0 ⟂ W ≥ 0
//   an equality row (−∞, ∞)                        λ = p − m:  p ≥ 0 ⟂ W ≥ 0,  m ≥ 0 ⟂ −W ≥ 0
//   a friction row, bounds ±μ Σ λc                 λ = p − m and a slip speed s:
//        p ≥ 0 ⟂ W + s ≥ 0,   m ≥ 0 ⟂ −W + s ≥ 0,   s ≥ 0 ⟂ μ Σ λc − p − m ≥ 0
// with W = J B λ − η. Inside the friction bounds s = 0 and W = 0 (sticking); at +μ Σ λc,
// W = −s ≤ 0 (sliding, the friction at its bound); in the plane the Coulomb cone is exactly
// these two directions, so this is Coulomb friction, not an approximation of it (Stewart and
// Trinkle 1996; Anitescu and Potra 1997). M is not positive semidefinite once friction is in,
// and Lemke may then end in a ray: the result says so. An MLCP of equality rows alone (a chain of
// joints) has no complementarity left: J B λ = η is solved directly (LDLᵀ); a singular J B
// (dependent rows) gets the solution of least |λ| when there is one, and is reported as a ray
// when there is none.
#pragma once

#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/QR>

#include "constraints/lemke.h"
#include "constraints/mlcp.h"

namespace lamina {

struct ExactSolution {
  LemkeStatus status = LemkeStatus::solved;
  Eigen::VectorXd lambda;  // λ of every row when solved, in N or N·m
  int pivots = 0;          // Lemke's pivots
};

// Whether every row has a form above: bounds [0, ∞), (−∞, ∞) or a friction row's ±μ Σ λc.
bool has_exact_form(const Mlcp& mlcp);

// Throws std::invalid_argument for a row whose fixed bounds are not [0, ∞) or (−∞, ∞).
ExactSolution solve_mlcp_exactly(const Mlcp& mlcp);

// The same solve with its memory kept from solve to solve: an MLCP of the rows and kinds solved
// last is solved again without allocating (an island of a World's step, every step), but for
// a singular J B of equality rows, whose least-|λ| solve allocates.
class ExactMlcpSolver {
 public:
  // As solve_mlcp_exactly; λ of every row is lambda() when solved (zeros otherwise).
  LemkeStatus solve(const Mlcp& mlcp);
  const Eigen::VectorXd& lambda() const { return lambda_; }
  int pivots() const { return pivots_; }  // Lemke's pivots (0 for equality rows only)

 private:
  // Row i's LCP variables: p (its λ, or λ's positive part), then m and s where it has them
  // (−1 where it has not).
  struct Variables {
    int p, m, s;
  };
  void delassus(const Mlcp& mlcp);
  LemkeStatus solve_equalities(const Mlcp& mlcp);

  Eigen::MatrixXd JB_;           // J B of the rows
  Eigen::VectorXd eta_;          // η of the rows
  Eigen::VectorXd lambda_;       // the answer
  Eigen::VectorXd residual_;     // J B λ − η, for checking an equality solve
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  std::vector<Variables> vars_;  // each row's LCP variables
  Eigen::MatrixXd M_;            // the LCP (M, q)
  Eigen::VectorXd q_;
  LemkeSolver lemke_;
  int pivots_ = 0;
};

}  // namespace lamina
