// The powers of ten that the shortest-decimal writer (shortest_number.cpp) multiplies by, as
// the two methods it uses define them, computed once, exactly, from their definitions (a small
// big-integer routine in powers_of_ten.cpp, no table in the source), and the logarithms that
// pick one.
#pragma once

#include <cstdint>

namespace lamina {

// ⌊log10 2^e⌋, ⌊log10 (3/4 · 2^e)⌋ and ⌊log2 10^e⌋ for |e| ≤ 1100, in fixed point (the
// constants are ⌊log10 2 · 2^41⌋, ⌊log10 3/4 · 2^41⌋ and ⌊log2 10 · 2^38⌋; right shifts of
// negative numbers floor on every compiler Lamina builds with).
inline int floor_log10_pow2(int e) { return static_cast<int>((e * 661971961083LL) >> 41); }
inline int floor_log10_three_quarters_pow2(int e) {
  return static_cast<int>((e * 661971961083LL - 274743187321LL) >> 41);
}
inline int floor_log2_pow10(int e) { return static_cast<int>((e * 913124641741LL) >> 38); }

// Schubfach's scaled powers: g(k) = ⌊10^−k 2^(125 − ⌊log2 10^−k⌋)⌋ + 1, a 126-bit number in
// [2^125, 2^126], held as its high and low 63 bits. k runs over the decimal exponents of
// normal doubles.
constexpr int scaled_k_min = -324;
constexpr int scaled_k_max = 292;
struct ScaledPower {
  std::uint64_t high;  // g >> 63
  std::uint64_t low;   // g mod 2^63
};
// g(k) for scaled_k_min ≤ k ≤ scaled_k_max, at [k − scaled_k_min].
const ScaledPower* scaled_powers();

// Dragonbox's scaled powers: φ(k) = ⌈10^k 2^(127 − ⌊log2 10^k⌋)⌉, a 128-bit number in
// [2^127, 2^128), held as its high and low 64 bits. k runs over what Dragonbox asks for a
// normal double v: about 2 − log10 v.
constexpr int wide_k_min = -292;
constexpr int wide_k_max = 326;
struct WidePower {
  std::uint64_t high;
  std::uint64_t low;
};
// φ(k) for wide_k_min ≤ k ≤ wide_k_max, at [k − wide_k_min].
const WidePower* wide_powers();

}  // namespace lamina
