#include "scene/powers_of_ten.h"

#include <algorithm>
#include <array>
#include <vector>

namespace lamina {
namespace {

using u64 = std::uint64_t;

// A non-negative integer of any size, little-endian in base 2^32: enough to compute g(k) and
// φ(k) exactly, once, from their definitions.
class BigNumber {
 public:
  explicit BigNumber(std::vector<std::uint32_t> limbs) : limbs_(std::move(limbs)) {}
  static BigNumber power_of_two(int exponent) {
    std::vector<std::uint32_t> limbs(static_cast<std::size_t>(exponent / 32 + 1), 0);
    limbs.back() = std::uint32_t{1} << (exponent % 32);
    return BigNumber(std::move(limbs));
  }
  void multiply(std::uint32_t m) {
    u64 carry = 0;
    for (std::uint32_t& limb : limbs_) {
      const u64 product = u64{limb} * m + carry;
      limb = static_cast<std::uint32_t>(product);
      carry = product >> 32;
    }
    if (carry != 0) limbs_.push_back(static_cast<std::uint32_t>(carry));
  }
  void divide(std::uint32_t d) {  // by d, rounding down
    u64 rest = 0;
    for (auto limb = limbs_.rbegin(); limb != limbs_.rend(); ++limb) {
      const u64 part = (rest << 32) | *limb;
      *limb = static_cast<std::uint32_t>(part / d);
      rest = part % d;
    }
  }
  // Whether any bit below `bit` is set.
  bool any_below(int bit) const {
    for (int b = 0; b < bit; ++b) {
      if (b / 32 < static_cast<int>(limbs_.size()) &&
          ((limbs_[static_cast<std::size_t>(b / 32)] >> (b % 32)) & 1u) != 0) {
        return true;
      }
    }
    return false;
  }
  // Bits [from, from + count) as a number, count ≤ 64; bits below 0 and above the top are 0.
  u64 bits(int from, int count) const {
    u64 value = 0;
    for (int i = count - 1; i >= 0; --i) {
      const int bit = from + i;
      const bool set = bit >= 0 && bit / 32 < static_cast<int>(limbs_.size()) &&
                       ((limbs_[static_cast<std::size_t>(bit / 32)] >> (bit % 32)) & 1u) != 0;
      value = (value << 1) | (set ? 1u : 0u);
    }
    return value;
  }

 private:
  std::vector<std::uint32_t> limbs_;
};

// g(k) from ⌊n 2^−shift⌋ with n = 10^−k 2^(125 − ⌊log2 10^−k⌋ + shift).
ScaledPower scaled_power(const BigNumber& n, int shift) {
  constexpr u64 mask63 = (u64{1} << 63) - 1;
  ScaledPower g{n.bits(shift + 63, 63), n.bits(shift, 63) + 1};
  if (g.low > mask63) {  // the + 1 carried
    g.low = 0;
    g.high += 1;
  }
  return g;
}

// Both methods' tables: their powers of ten of 1 and above from one run of 10^n upwards, and
// those below 1 from one run of ⌊2^quotient_top / 10^n⌋ downwards.
struct PowerTables {
  std::array<ScaledPower, scaled_k_max - scaled_k_min + 1> scaled{};  // g(k) at [k − scaled_k_min]
  std::array<WidePower, wide_k_max - wide_k_min + 1> wide{};          // φ(k) at [k − wide_k_min]
};

// The quotients are divided down from 2^quotient_top: bits enough for the smallest power, 10^−292
// (about 2^−970), and 128 more.
constexpr int quotient_top = 1152;

PowerTables make_power_tables() {
  PowerTables tables;
  // 10^n, n ≥ 0: Schubfach's k = −n, g(k) − 1 the bits of 10^−k from ⌊log2 10^−k⌋ − 125 up;
  // Dragonbox's k = n, φ(k) the bits of 10^k from ⌊log2 10^k⌋ − 127 up, rounded up when bits
  // below are cut off
  BigNumber power_of_ten({1});
  for (int n = 0; n <= std::max(-scaled_k_min, wide_k_max); ++n) {
    if (-n >= scaled_k_min) {
      tables.scaled[static_cast<std::size_t>(-n - scaled_k_min)] =
          scaled_power(power_of_ten, floor_log2_pow10(n) - 125);
    }
    if (n <= wide_k_max) {
      const int from = floor_log2_pow10(n) - 127;
      WidePower phi{power_of_ten.bits(from + 64, 64), power_of_ten.bits(from, 64)};
      if (from > 0 && power_of_ten.any_below(from) && ++phi.low == 0) ++phi.high;
      tables.wide[static_cast<std::size_t>(n - wide_k_min)] = phi;
    }
    power_of_ten.multiply(10);
  }
  // ⌊2^quotient_top / 10^n⌋, n ≥ 1, divided down by 10 one n at a time (⌊⌊x/a⌋/b⌋ = ⌊x/(ab)⌋
  // for integers). Schubfach's k = n: ⌊2^m / 10^k⌋ = ⌊⌊2^top / 10^k⌋ / 2^(top − m)⌋ with
  // m = 125 − ⌊log2 10^−k⌋ ≤ 1096 < top. Dragonbox's k = −n: φ(k) = ⌊2^(127 − ⌊log2 10^k⌋) /
  // 10^−k⌋ + 1 (never a whole number: 5^−k divides no power of 2).
  BigNumber quotient = BigNumber::power_of_two(quotient_top);
  for (int n = 1; n <= std::max(scaled_k_max, -wide_k_min); ++n) {
    quotient.divide(10);
    if (n <= scaled_k_max) {
      const int m = 125 - floor_log2_pow10(-n);
      tables.scaled[static_cast<std::size_t>(n - scaled_k_min)] =
          scaled_power(quotient, quotient_top - m);
    }
    if (-n >= wide_k_min) {
      const int from = quotient_top - 127 + floor_log2_pow10(-n);
      WidePower phi{quotient.bits(from + 64, 64), quotient.bits(from, 64)};
      if (++phi.low == 0) ++phi.high;
      tables.wide[static_cast<std::size_t>(-n - wide_k_min)] = phi;
    }
  }
  return tables;
}

const PowerTables& power_tables() {
  static const PowerTables tables = make_power_tables();
  return tables;
}

}  // namespace

const ScaledPower* scaled_powers() { return power_tables().scaled.data(); }

const WidePower* wide_powers() { return power_tables().wide.data(); }

}  // namespace lamina
