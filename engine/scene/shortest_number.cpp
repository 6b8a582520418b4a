#include "scene/shortest_number.h"

#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <vector>

// The shortest decimal that reads back to a double, found by Raffaello Giulietti's Schubfach
// method ("The Schubfach way to render doubles", 2020; the algorithm of Java's Double.toString
// since JDK 19), written in the layout of std::to_chars: the same characters, byte for byte
// (tests/test_trace.cpp compares the two on 1.4 million doubles). It exists because a trace
// writes about 9 000 numbers a step and std::to_chars spent 517 instructions on each, more
// than the physics of the step they record (issue 19); this takes 311 (docs/performance.md).
// Zero is written directly; subnormal, infinite and NaN values go to std::to_chars (a trace
// never has them; subnormals are the corner of the method, where a few bits leave many
// decimals to choose from).
namespace lamina {
namespace {

using u64 = std::uint64_t;
using u128 = unsigned __int128;

// A double v = c 2^q with 2^52 ≤ c < 2^53 (normal) is rounded to from every real in the
// interval R_v around it; the shortest decimal in R_v is sought on the grid 10^k with k chosen
// so that R_v is narrower than 10^(k+1): there is at most one multiple of 10^(k+1) in it (the
// shortest if it is there), else the multiple of 10^k next to v on the side R_v holds.

// ⌊log10 2^e⌋, ⌊log10 (3/4 · 2^e)⌋ and ⌊log2 10^e⌋ for |e| ≤ 1100, in fixed point (the
// constants are ⌊log10 2 · 2^41⌋, ⌊log10 3/4 · 2^41⌋ and ⌊log2 10 · 2^38⌋; right shifts of
// negative numbers floor on every compiler Lamina builds with).
int floor_log10_pow2(int e) { return static_cast<int>((e * 661971961083LL) >> 41); }
int floor_log10_three_quarters_pow2(int e) {
  return static_cast<int>((e * 661971961083LL - 274743187321LL) >> 41);
}
int floor_log2_pow10(int e) { return static_cast<int>((e * 913124641741LL) >> 38); }

// The scaled powers of ten: g(k) = ⌊10^−k 2^(125 − ⌊log2 10^−k⌋)⌋ + 1, a 126-bit number in
// [2^125, 2^126], held as its high and low 63 bits. k runs over the decimal exponents of
// normal doubles.
constexpr int k_min = -324;
constexpr int k_max = 292;
struct ScaledPower {
  u64 high;  // g >> 63
  u64 low;   // g mod 2^63
};

// A non-negative integer of any size, little-endian in base 2^32: enough to compute g(k)
// exactly, once, from its definition.
class BigNumber {
 public:
  explicit BigNumber(std::vector<std::uint32_t> limbs) : limbs_(std::move(limbs)) {}
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

using ScaledPowers = std::array<ScaledPower, k_max - k_min + 1>;

ScaledPowers make_scaled_powers() {
  ScaledPowers table{};
  // k ≤ 0: 10^−k is an integer, g(k) − 1 its bits from ⌊log2 10^−k⌋ − 125 up.
  BigNumber power_of_ten({1});
  for (int k = 0; k >= k_min; --k) {
    table[static_cast<std::size_t>(k - k_min)] = scaled_power(power_of_ten, floor_log2_pow10(-k) - 125);
    power_of_ten.multiply(10);
  }
  // k > 0: ⌊2^m / 10^k⌋ = ⌊⌊2^top / 10^k⌋ / 2^(top − m)⌋, the inner floor divided down by 10
  // one k at a time (⌊⌊x/a⌋/b⌋ = ⌊x/(ab)⌋ for integers); m = 125 − ⌊log2 10^−k⌋ ≤ 1096 < top.
  constexpr int top = 1152;
  std::vector<std::uint32_t> limbs(top / 32 + 1, 0);
  limbs.back() = 1;
  BigNumber quotient(std::move(limbs));
  for (int k = 1; k <= k_max; ++k) {
    quotient.divide(10);
    const int m = 125 - floor_log2_pow10(-k);
    table[static_cast<std::size_t>(k - k_min)] = scaled_power(quotient, top - m);
  }
  return table;
}

const ScaledPower& scaled_power_of(int k) {
  static const ScaledPowers table = make_scaled_powers();
  return table[static_cast<std::size_t>(k - k_min)];
}

// ⌊c g 2^−127⌋ rounded to odd (its lowest bit set if any bit below was): Schubfach's r_o.
u64 round_to_odd(const ScaledPower& g, u64 c) {
  constexpr u64 mask63 = (u64{1} << 63) - 1;
  const u128 by_low = u128{g.low} * c;
  const u128 by_high = u128{g.high} * c;
  const u64 middle = (static_cast<u64>(by_high) >> 1) + static_cast<u64>(by_low >> 64);
  const u64 floor = static_cast<u64>(by_high >> 64) + (middle >> 63);
  return floor | (((middle & mask63) + mask63) >> 63);
}

// v = digits · 10^exponent, digits without trailing zeros.
struct Decimal {
  u64 digits;
  int exponent;
};

Decimal without_trailing_zeros(Decimal d) {
  while (d.digits % 10 == 0) {
    d.digits /= 10;
    ++d.exponent;
  }
  return d;
}

// The shortest decimal in R_v of v = c 2^q (normal, positive); of two, the nearer to v, and
// of two as near, the one with an even last digit.
Decimal shortest_decimal(u64 c, int q) {
  if (q < 0 && q > -53 && ((c >> -q) << -q) == c) return without_trailing_zeros({c >> -q, 0});
  // 2^52 2^q has a closer neighbour below, unless it is the least normal double
  const bool regular = c != (u64{1} << 52) || q == -1074;
  const u64 open = c & 1;                     // R_v excludes its ends when c is odd
  const u64 cb = c << 2;                      // 4 v, and its interval's ends, in units of 2^q
  const u64 cb_right = cb + 2;
  const u64 cb_left = regular ? cb - 2 : cb - 1;
  const int k = regular ? floor_log10_pow2(q) : floor_log10_three_quarters_pow2(q);
  const int h = q + floor_log2_pow10(-k) + 2;  // 1 … 4
  const ScaledPower& g = scaled_power_of(k);
  const u64 vb = round_to_odd(g, cb << h);      // 4 v / 10^k, rounded to odd
  const u64 vb_left = round_to_odd(g, cb_left << h);
  const u64 vb_right = round_to_odd(g, cb_right << h);
  const u64 s = vb >> 2;  // ⌊v / 10^k⌋: 16 or 17 digits for a normal v
  // The one multiple of 10^(k+1) that R_v may hold, below v or above it: the shortest.
  const u64 s10 = s / 10 * 10;
  const u64 t10 = s10 + 10;
  const bool s10_in = vb_left + open <= s10 << 2;
  const bool t10_in = (t10 << 2) + open <= vb_right;
  if (s10_in != t10_in) return without_trailing_zeros({s10_in ? s10 : t10, k});
  // Else the multiple of 10^k either side of v that R_v holds; of two, the nearer. (These
  // end in no zero: one that did would be the multiple of 10^(k+1) above. Chosen without
  // branches: which of the two it is, is a coin toss a branch predictor loses half the time.)
  const u64 t = s + 1;
  const bool s_in = vb_left + open <= s << 2;
  const bool t_in = (t << 2) + open <= vb_right;
  const auto above_middle = static_cast<std::int64_t>(vb - ((s + t) << 1));  // 4v − 2(s + t)
  const bool nearer_s = above_middle < 0 || (above_middle == 0 && (s & 1) == 0);
  const bool take_s = s_in != t_in ? s_in : nearer_s;
  return {take_s ? s : t, k};
}

constexpr char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The number of decimal digits of d > 0.
int digit_count(u64 d) {
  static constexpr u64 powers_of_ten[] = {
      1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u, 100000000u, 1000000000u,
      10000000000u, 100000000000u, 1000000000000u, 10000000000000u, 100000000000000u,
      1000000000000000u, 10000000000000000u, 100000000000000000u, 1000000000000000000u,
      10000000000000000000u};
  const int n = floor_log10_pow2(64 - __builtin_clzll(d));  // d < 2^bits ≤ 10^(n+1)
  return d >= powers_of_ten[n] ? n + 1 : n;
}

// The eight decimal digits of m < 10^8, leading zeros included, at `out`, made side by side in
// the lanes of one 64-bit word (the first character is its lowest byte): m's two halves of
// four digits in 32-bit lanes, each split into two pairs in 16-bit lanes (v/100 as
// v · 10486 / 2^20, exact for v < 10^4), each pair into two digits in bytes (p/10 as
// p · 103 / 2^10, exact for p < 100). All 10^8 were checked against printf's.
void write_eight_digits(char* out, std::uint32_t m) {
  const u64 halves = (m / 10000) | (u64{m % 10000} << 32);
  const u64 hundreds = ((halves * 10486) >> 20) & 0x0000007f0000007fu;
  const u64 pairs = hundreds | ((halves - hundreds * 100) << 16);
  const u64 tens = ((pairs * 103) >> 10) & 0x000f000f000f000fu;
  const u64 digits = tens | ((pairs - tens * 10) << 8);
  const u64 text = digits | 0x3030303030303030u;  // '0' in every byte
  std::memcpy(out, &text, sizeof text);
}

// The decimal digits of a number, made eight at a time into a buffer with room after them, so
// that they go to their places in copies of one constant size (a few moves, not a call).
class DigitText {
 public:
  static constexpr int block = 24;  // characters a copy writes: room the destination must have

  // The last n ≤ 24 digits of d < 10^24 (zeros before it if n is more than its digits).
  DigitText(u64 d, int n) : n_(n) {
    const u64 high = d / 100000000;  // the digits before the last eight
    const u64 top = high / 100000000;  // and before the last sixteen
    write_eight_digits(text_ + 24, static_cast<std::uint32_t>(d - high * 100000000));
    if (n > 8) write_eight_digits(text_ + 16, static_cast<std::uint32_t>(high - top * 100000000));
    if (n == 17) {  // a double's longest: its first digit alone
      text_[15] = static_cast<char>('0' + top);
    } else if (n > 17) {
      write_eight_digits(text_ + 8, static_cast<std::uint32_t>(top));
    }
    std::memset(text_ + 32, 0, block);  // what a copy takes after the last digit
  }
  // The digits from the `from`-th on (and what follows them, up to `block` characters) at `out`.
  void copy(char* out, int from = 0) const { std::memcpy(out, text_ + 32 - n_ + from, block); }

 private:
  char text_[32 + block];  // the digits end at 32
  int n_;
};

// The digits of a whole v = c 2^q, q ≥ 0, below 10^24, at `out` (room for 32); returns
// their end.
char* write_whole_digits(char* out, u64 c, int q) {
  constexpr u64 ten_to_16 = 10000000000000000u;
  const u128 v = u128{c} << q;
  if (v <= ~u64{0}) {
    const int n = digit_count(static_cast<u64>(v));
    DigitText(static_cast<u64>(v), n).copy(out);
    return out + n;
  }
  const auto high = static_cast<u64>(v / ten_to_16);  // below 10^8
  const int n = digit_count(high);
  DigitText(high, n).copy(out);
  DigitText(static_cast<u64>(v % ten_to_16), 16).copy(out + n);
  return out + n + 16;
}

// ".0" at `out`: an integer's text made to read as floating point; returns its end.
char* point_zero(char* out) {
  out[0] = '.';
  out[1] = '0';
  return out + 2;
}

// d, the shortest decimal of v = c 2^q, in std::to_chars' plain form: fixed notation ("0.001",
// "250", "12.5") unless scientific ("1e-05", "2.5e+21") is shorter, and with `float_form` an
// integer's text with ".0" after it ("250.0"). Like std::to_chars, a whole v past 2^53 is
// written with all its digits ("316070159402654208", not "316070159402654200"): fixed notation
// is printf's %f.
// `out` has room for 42 characters (digits.copy after 17 digits and a point).
char* write_decimal(char* out, Decimal d, u64 c, int q, bool float_form) {
  const int n = digit_count(d.digits);
  const DigitText digits(d.digits, n);
  const int exponent10 = d.exponent + n - 1;  // of the first digit
  const int magnitude = exponent10 < 0 ? -exponent10 : exponent10;
  const int scientific_length = n + (n > 1 ? 1 : 0) + 2 + (magnitude >= 100 ? 3 : 2);
  const int point = n + d.exponent;  // digits before the decimal point
  const int fixed_length = d.exponent >= 0 ? n + d.exponent : point > 0 ? n + 1 : 2 - d.exponent;
  if (fixed_length <= scientific_length) {
    if (d.exponent >= 0) {  // "250"
      if (q > 0) {
        out = write_whole_digits(out, c, q);
      } else {
        digits.copy(out);
        std::memset(out + n, '0', static_cast<std::size_t>(d.exponent));
        out += fixed_length;
      }
      return float_form ? point_zero(out) : out;
    }
    if (point > 0) {  // "12.5"
      digits.copy(out);
      digits.copy(out + point + 1, point);
      out[point] = '.';
      return out + fixed_length;
    }
    // "0.001": fixed is as short as scientific only while −point ≤ 3 (2 − e ≤ n + 5)
    std::memcpy(out, "0.000", 5);
    digits.copy(out + 2 - point);
    return out + fixed_length;
  }
  digits.copy(out);  // "2.5e+21": the first digit, the point, the others
  out[1] = '.';
  digits.copy(out + 2, 1);
  out += n > 1 ? n + 1 : 1;
  *out++ = 'e';
  *out++ = exponent10 < 0 ? '-' : '+';
  if (magnitude >= 100) *out++ = static_cast<char>('0' + magnitude / 100);
  std::memcpy(out, digit_pairs + 2 * (magnitude % 100), 2);
  return out + 2;
}

// Room for to_chars: a double takes at most 24 characters ("-2.2250738585072014e-308").
constexpr int shortest_room = shortest_float_length - 2;

// The one formatter of both forms: x written at `first`, which has shortest_float_length
// characters; returns the end of it. With `float_form`, a text that would read as an integer
// ("2", "-0") has ".0" after it; "0.5", "1e+21", "inf" and "nan" read as floating point already.
char* write_shortest(char* first, double x, bool float_form) {
  u64 bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased_exponent = static_cast<int>((bits >> 52) & 0x7ff);
  if ((bits << 1) == 0) {  // ±0, common in a trace
    if (bits != 0) *first++ = '-';
    *first++ = '0';
    return float_form ? point_zero(first) : first;
  }
  if (biased_exponent == 0 || biased_exponent == 0x7ff) {  // subnormal, infinite, NaN
    return std::to_chars(first, first + shortest_room, x).ptr;
  }
  if ((bits >> 63) != 0) *first++ = '-';
  const u64 c = (bits & ((u64{1} << 52) - 1)) | (u64{1} << 52);
  const int q = biased_exponent - 1075;
  return write_decimal(first, shortest_decimal(c, q), c, q, float_form);
}

}  // namespace

std::string shortest_number(double x) {
  char text[shortest_float_length];
  return std::string(text, write_shortest(text, x, false));
}

void append_shortest(std::string& out, double x) {
  char text[shortest_float_length];
  out.append(text, write_shortest(text, x, true));
}

char* write_shortest_float(char* first, double x) { return write_shortest(first, x, true); }

}  // namespace lamina
