// One row's share of the MLCP of eq. 3-16, in the layout of N components per block
// (block_layout.h): the text's Convert B_i = M⁻¹ J_iᵀ, d_i = J_i · B_i and
// η_i = ζ_i/Δt − J_i (V/Δt + M⁻¹ F_ext). assemble_mlcp writes them in the text's form (N = 6);
// the PGS workspace packs them (N = 3 in the plane). Defined here, inline, so that packing
// writes them where they go without a copy in between.
#pragma once

#include <array>
#include <vector>

#include "constraints/block_layout.h"
#include "constraints/constraint_row.h"
#include "motion/rigid_body.h"

namespace lamina {

// M⁻¹ J_b for one body's block: [m⁻¹ J_v; I⁻¹ J_ω] (eq. 3-12, the text's Convert).
Vec6 inverse_mass_times(const RigidBody& body, const Vec6& block);

// The same in the layout of N components. In the plane, where I⁻¹ turns z into itself, it is
// [m⁻¹ J_x, m⁻¹ J_y, (I⁻¹)_zz J_ωz]: the numbers of the 6-vector form without its zero terms.
template <int N>
Block<N> convert(const RigidBody& body, const Block<N>& block);
template <>
inline Block<6> convert<6>(const RigidBody& body, const Block<6>& block) {
  return inverse_mass_times(body, block);
}
template <>
inline Block<3> convert<3>(const RigidBody& body, const Block<3>& block) {
  // eq. 3-12 in the plane: M⁻¹ = diag(m⁻¹, m⁻¹, (I⁻¹)_zz) on [v_x v_y ω_z]
  return Block<3>(body.inverse_mass * block[0], body.inverse_mass * block[1],
                  body.inverse_inertia_world(2, 2) * block[2]);
}

// Row i's terms: its J and B blocks, η_i and d_i.
template <int N>
struct RowTerms {
  std::array<Block<N>, 2> J;  // J_i's blocks (Jsp); zero for a missing second body
  std::array<Block<N>, 2> B;  // M⁻¹ of each block (the text's Convert, Bsp); zero likewise
  double eta = 0.0;           // η_i, in m/s² or rad/s²
  double d = 0.0;             // d_i = J_i · B_i
};

// Row i's terms, given every body's V/Δt + M⁻¹ F_ext (`unconstrained`, see
// unconstrained_velocities; zeros give η_i = ζ_i/Δt, the bodies from rest under no force).
// N = 3 asks the row and its bodies to lie in the plane (J_i's and B_i's v_z, ω_x, ω_y zero);
// the terms are then those of N = 6, cut.
template <int N>
RowTerms<N> assemble_row(const std::vector<RigidBody>& bodies, const ConstraintRow& row,
                         const std::vector<Vec6>& unconstrained, double dt) {
  RowTerms<N> terms;
  for (int k = 0; k < 2; ++k) {
    terms.J[k] = cut<N>(row.Jsp[k]);
    // The text's Convert: Bᵀ_i = J_i M⁻¹, block by block
    terms.B[k] = row.Jmap[k] < 0 ? Block<N>::Zero().eval()
                                 : convert<N>(bodies[row.Jmap[k]], terms.J[k]);
  }
  // d_i = J_i · B_i
  terms.d = ordered_dot<N>(terms.J[0], terms.B[0]) + ordered_dot<N>(terms.J[1], terms.B[1]);
  // J_i (V/Δt + M⁻¹ F_ext), summed as row_times sums it
  double j_u = ordered_dot<N>(terms.J[0], cut<N>(unconstrained[row.Jmap[0]]));
  if (!row.is_one_body()) j_u += ordered_dot<N>(terms.J[1], cut<N>(unconstrained[row.Jmap[1]]));
  // eq. 3-16: η = ζ/Δt − J (V/Δt + M⁻¹ F_ext)
  terms.eta = row.zeta / dt - j_u;
  return terms;
}

}  // namespace lamina
