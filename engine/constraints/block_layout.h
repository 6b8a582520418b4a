// How much of a Jacobian block the solver stores: the planar-aware layout.
//
// A block of J or of B = M⁻¹ Jᵀ is a 6-vector [v; ω] (eq. 3-5, "Computing Jacobian"). In Lamina's
// plane, every row's v_z, ω_x and ω_y are zero (planar.h), and so are B's when each body's I⁻¹
// turns the z axis into itself. The solver then keeps N = 3 components, [v_x v_y ω_z], instead
// of N = 6, and leaves out only products with an exact zero.
//
// Dot products are summed component by component in order (ordered_dot), so a sum over the 3
// kept components equals the sum over all 6: adding an exact zero changes nothing. Either
// layout gives the same numbers, bit for bit.
#pragma once

#include <array>

#include "kinematics/math_types.h"

namespace lamina {

template <int N>
using Block = Eigen::Matrix<double, N, 1>;  // a block in the layout of N components

// A 6-vector cut to a layout's components: all six, or [v_x v_y ω_z].
template <int N>
Block<N> cut(const Vec6& v);
template <>
inline Block<6> cut<6>(const Vec6& v) { return v; }
template <>
inline Block<3> cut<3>(const Vec6& v) { return Block<3>(v[0], v[1], v[5]); }

// A block back as a 6-vector, the left-out components zero.
template <int N>
Vec6 widen(const Block<N>& block);
template <>
inline Vec6 widen<6>(const Block<6>& block) { return block; }
template <>
inline Vec6 widen<3>(const Block<3>& block) {
  Vec6 v = Vec6::Zero();
  v[0] = block[0];
  v[1] = block[1];
  v[5] = block[2];
  return v;
}

// Whether a 6-vector lies in the plane: v_z = ω_x = ω_y = 0.
inline bool in_plane(const Vec6& v) { return v[2] == 0.0 && v[3] == 0.0 && v[4] == 0.0; }

// x · y = Σ_k x_k y_k, summed from k = 0 up.
template <int N>
double ordered_dot(const Block<N>& x, const Block<N>& y);
template <>
inline double ordered_dot<6>(const Block<6>& x, const Block<6>& y) {
  double sum = x[0] * y[0];
  for (int k = 1; k < 6; ++k) sum += x[k] * y[k];
  return sum;
}
template <>
inline double ordered_dot<3>(const Block<3>& x, const Block<3>& y) {
  // (x_0 y_0 + x_1 y_1) + x_2 y_2: the first two as one pair of lanes, the same sum
  return x.head<2>().dot(y.head<2>()) + x[2] * y[2];
}

// J_i · X for a row's two blocks and two per-body vectors (the text's Multiply, one row): the
// second block only when the row has a second body (Jmap[1] ≥ 0), so a one-body row never reads
// a missing body's vector. Every J V, J a and J u of the engine is this sum.
template <int N>
double row_dot(const std::array<Block<N>, 2>& J, const Block<N>& x0, const Block<N>& x1,
               bool two_bodies) {
  double sum = ordered_dot<N>(J[0], x0);
  if (two_bodies) sum += ordered_dot<N>(J[1], x1);
  return sum;
}

}  // namespace lamina
