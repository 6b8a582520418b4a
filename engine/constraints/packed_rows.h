// The rows of the MLCP as they are assembled once per step and swept (eq. 3-16, 3-24): one
// struct per row, contiguous, holding the text's Jsp, Bsp (its Convert), Jmap, η_i, 1/d_i and
// the bounds side by side, each block in the layout of N components (block_layout.h: all six,
// or [v_x v_y ω_z] in the plane).
//
// The three products every use of the MLCP is made of are defined here, once:
//   a = B λ        transpose_multiply  (the text's TransposeMultiply, scaled by λ[i]: the text
//                                       writes λ[b1], λ[b2], indexing λ by body)
//   J_i · X        row_dot             (the text's Multiply, guarding Jmap[1] = −1, which the
//                                       text's PGS loop does not; docs/the-text.md, chapter 3)
//   F_c = Jᵀ λ     add_force_term      (eq. 3-11)
// Mlcp (mlcp.h) assembles and views the rows; PgsSolver (pgs_solver.h) sweeps them.
#pragma once

#include <array>
#include <vector>

#include "constraints/block_layout.h"

namespace lamina {

struct PackedRowScalars {
  std::array<int, 2> map{-1, -1};  // Jmap: body indices, map[1] = −1 for a one-body row
  double eta = 0.0;                // η_i, in m/s² or rad/s² (eq. 3-16)
  double inverse_d = 0.0;          // 1/d_i, d_i = J_i · B_i
  double lambda_min = 0.0;         // λ⁻ of a row with fixed bounds, in N
  double lambda_max = 0.0;         // λ⁺ of a row with fixed bounds, in N
  int friction_of = -1;            // the (first) contact row bounding a friction row, or −1
  int friction_count = 1;          // how many consecutive contact rows from friction_of bound it
  double mu = 0.0;                 // μ of a friction row
  double zeta = 0.0;               // ζ_i, the velocity asked of J_i V(t+Δt), in m/s or rad/s

  bool two_bodies() const { return map[1] >= 0; }
};

// The scalars a ConstraintRow (constraint_row.h) and a packed row both hold, copied from one
// to the other: ζ, the fixed bounds, and a friction row's contact rows and μ.
template <class From, class To>
void copy_row_scalars(const From& from, To& to) {
  to.zeta = from.zeta;
  to.lambda_min = from.lambda_min;
  to.lambda_max = from.lambda_max;
  to.friction_of = from.friction_of;
  to.friction_count = from.friction_count;
  to.mu = from.mu;
}

template <int N>
struct PackedRow : PackedRowScalars {
  static constexpr int size = N;  // components per block
  std::array<Block<N>, 2> J;  // J_i's blocks for map[0], map[1] (Jsp); zero for a missing body
  std::array<Block<N>, 2> B;  // B_i's blocks, M⁻¹ J_iᵀ (Bsp); zero likewise
};

template <int N>
using PackedRows = std::vector<PackedRow<N>>;

// The bounds of a row for the current λ (λ[0..s)): fixed, or ±μ λc for a friction row
// (eq. 3-26), λc being its contact row's λ or the sum over a manifold's contact rows.
// `Row` is a packed row or a ConstraintRow. Always inlined: called once per row per sweep, and
// GCC left it a call (a fifth of PGS's instructions on a pyramid went to it: 105 M → 84 M for
// 60 steps of pyramid:20, the same λ bit for bit).
template <class Row>
[[gnu::always_inline]] inline std::array<double, 2> bounds_of(const Row& row, const double* lambda) {
  if (row.friction_of < 0) return {row.lambda_min, row.lambda_max};
  double normal = lambda[row.friction_of];
  for (int k = 1; k < row.friction_count; ++k) normal += lambda[row.friction_of + k];
  // eq. 3-26: a friction row is bounded by ±μ λc
  const double limit = row.mu * normal;
  return {-limit, limit};
}

// J_i · X for per-body blocks X.
template <int N>
double row_dot(const PackedRow<N>& row, const std::vector<Block<N>>& per_body) {
  const Block<N>& second = row.two_bodies() ? per_body[row.map[1]] : per_body[row.map[0]];
  return row_dot<N>(row.J, per_body[row.map[0]], second, row.two_bodies());
}

// Row i's term of a = B λ: a_b += λ_i B_i's block, for each of its bodies (a2 unused for a
// one-body row). A zero λ_i adds nothing and is skipped (a split-impulse solve starts from λ = 0).
template <int N>
void add_row_term(const PackedRow<N>& row, double lambda_i, Block<N>& a1, Block<N>& a2) {
  if (lambda_i == 0.0) return;
  a1 += lambda_i * row.B[0];
  if (row.two_bodies()) a2 += lambda_i * row.B[1];
}

// a = B λ, one block per body: the text's TransposeMultiply, scaled by λ[i].
template <int N>
void transpose_multiply(const PackedRows<N>& rows, int body_count, const double* lambda,
                        std::vector<Block<N>>& a) {
  a.assign(static_cast<std::size_t>(body_count), Block<N>::Zero());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PackedRow<N>& row = rows[i];
    add_row_term(row, lambda[i], a[row.map[0]], a[row.two_bodies() ? row.map[1] : row.map[0]]);
  }
}

// Row i's term of F_c = Jᵀ λ (eq. 3-11): f_b += λ_i J_i's block, for each of its bodies (f2
// unused for a one-body row). Every sum of the forces on a body adds its rows' terms in row
// order (Mlcp::add_constraint_forces, add_group_forces in mlcp.h).
template <int N>
void add_force_term(const PackedRow<N>& row, double lambda_i, Block<N>& f1, Block<N>& f2) {
  f1 += lambda_i * row.J[0];
  if (row.two_bodies()) f2 += lambda_i * row.J[1];
}

}  // namespace lamina
