#include "scene/shortest_number.h"

#include <charconv>
#include <cstdint>
#include <cstring>

#include "scene/powers_of_ten.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// The shortest decimal that reads back to a double, written in the layout of std::to_chars:
// the same characters, byte for byte (tests/test_trace.cpp compares the two on 1.4 million
// doubles). It exists because a trace writes about 9 000 numbers a step and std::to_chars
// spent 517 instructions on each, more than the physics of the step they record (issue 19);
// this takes 226 (docs/performance.md, "Traces"). The decimal is found by Junekey Jeon's
// Dragonbox (one 64 × 128-bit product) where the integer parts decide, which is 99 numbers in
// 100, and else by Raffaello Giulietti's Schubfach method ("The Schubfach way to render
// doubles", 2020; Java's Double.toString since JDK 19: three products, exact in every case);
// both tables of powers of ten are computed once, exactly, from their definitions. Zero is
// written directly; subnormal, infinite and NaN values go to std::to_chars (a trace never has
// them; subnormals are the corner of the method, where a few bits leave many decimals to
// choose from).
namespace lamina {
namespace {

using u64 = std::uint64_t;
__extension__ typedef unsigned __int128 u128;  // GCC and Clang's 128-bit integer

// A double v = c 2^q with 2^52 ≤ c < 2^53 (normal) is rounded to from every real in the
// interval R_v around it; the shortest decimal in R_v is sought on the grid 10^k with k chosen
// so that R_v is narrower than 10^(k+1): there is at most one multiple of 10^(k+1) in it (the
// shortest if it is there), else the multiple of 10^k next to v on the side R_v holds.

// Schubfach's g(k) and Dragonbox's φ(k) (scene/powers_of_ten.h), each table's start fetched
// once.
const ScaledPower& scaled_power_of(int k) {
  static const ScaledPower* const table = scaled_powers();
  return table[k - scaled_k_min];
}
const WidePower& wide_power_of(int k) {
  static const WidePower* const table = wide_powers();
  return table[k - wide_k_min];
}

// ⌊x φ 2^−128⌋ (the product's lowest 64 bits are not computed; Dragonbox's proofs allow it).
u64 multiply_high(u64 x, const WidePower& phi) {
  const u128 sum = u128{x} * phi.high + static_cast<u64>((u128{x} * phi.low) >> 64);
  return static_cast<u64>(sum >> 64);
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

// The first try, with one product instead of three: Junekey Jeon's Dragonbox ("Dragonbox: a
// new floating-point binary-to-decimal conversion algorithm", 2020), for v = c 2^q with
// c ≠ 2^52 (R_v = [v − 2^(q−1), v + 2^(q−1)], its ends in it when c is even). Scaled by 10^−m,
// m = ⌊log10 2^q⌋ − 2, R_v is δ = 2^q 10^−m wide, 100 ≤ δ < 1000: it holds at most one
// multiple of 1000 (then the shortest), and at least one of 100. With β = q + ⌊log2 10^−m⌋
// (6 … 9), the right end z = (2c + 1) 2^(q−1) 10^−m has ⌊z⌋ = ⌊((2c + 1) 2^β) φ(−m) 2^−128⌋
// and ⌊δ⌋ = ⌊φ(−m) 2^(β−127)⌋ (Dragonbox's theorems: exact for every double). The cases where
// the fractions decide — a multiple of 1000 at z or at the left end, v halfway between two
// multiples of 100 or near it (about one in a hundred) — are left to the exact method below:
// false, and nothing written.
bool shortest_decimal_by_one_product(u64 c, int q, Decimal& d) {
  const int m = floor_log10_pow2(q) - 2;
  const WidePower& phi = wide_power_of(-m);
  const int beta = q + floor_log2_pow10(-m);
  const u64 width = phi.high >> (63 - beta);                 // ⌊δ⌋
  const u64 z = multiply_high(((c << 1) | 1) << beta, phi);  // ⌊z⌋
  const u64 thousands = z / 1000;
  const u64 rest = z - thousands * 1000;
  // 1000 ⌊z / 1000⌋ is in R_v when rest < ⌊δ⌋ (then the shortest), unless it is z itself
  // (rest = 0: whether the right end is in R_v, the fraction decides). Else the multiple of
  // 100 nearest to v = z − δ/2, from (rest − δ/2 + 50) / 100, unless that is a whole number (v
  // at or near halfway). Which of the two it is, is a coin toss (δ/1000 is the chance of the
  // first): both are made and one kept without a branch, which a branch predictor would miss
  // half the time (docs/performance.md, "Traces"). The cases left to the exact method are
  // tested for both at once (a few more than needed: one in a hundred of the first).
  const u64 thousand_in = rest < width ? 1 : 0;
  const u64 from_thousands = rest - width / 2 + 50;  // wraps around when thousand_in: unused
  const u64 hundreds = from_thousands / 100;
  if ((rest == 0) | (rest == width) | (hundreds * 100 == from_thousands)) return false;
  const u64 hundred_mask = thousand_in - 1;  // all ones for the multiple of 100, else 0
  d = without_trailing_zeros({thousands + ((thousands * 9 + hundreds) & hundred_mask),
                              m + 3 - static_cast<int>(hundred_mask & 1)});
  return true;
}

Decimal shortest_decimal_exact(u64 c, int q);

// The shortest decimal in R_v of v = c 2^q (normal, positive); of two, the nearer to v, and
// of two as near, the one with an even last digit.
Decimal shortest_decimal(u64 c, int q) {
  if (q < 0 && q > -53 && ((c >> -q) << -q) == c) return without_trailing_zeros({c >> -q, 0});
  Decimal first_try{};
  if (c != (u64{1} << 52) && shortest_decimal_by_one_product(c, q, first_try)) return first_try;
  return shortest_decimal_exact(c, q);
}

// Schubfach's exact method (three products). 2^52 2^q has a closer neighbour below, unless it
// is the least normal double. Out of line, as the whole numbers past 2^53 below: kept apart,
// the rare cases leave the common one its registers.
[[gnu::noinline, gnu::cold]] Decimal shortest_decimal_exact(u64 c, int q) {
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

#if defined(__SSE2__)
// The sixteen decimal digits of x < 10^16, leading zeros included, at `out` (the first
// character at out[0]), made in the sixteen 16-bit lanes of two SSE2 registers, a lane per
// digit. x is cut into two halves of eight digits and each half into two groups of four (/10^4
// as · 3518437209 / 2^45, exact below 2^32), giving the groups a, b, c, d; each group v, times
// 4, fills the four 16-bit lanes of a 64-bit half, and lane j becomes t_j = ⌊v / 10^(3−j)⌋ by
// two high-half products: ⌊4v · m_j / 2^16⌋, then ⌊· 2^(16−s_j) / 2^16⌋, a right shift by s_j
// (SSE2 shifts all lanes alike). The pairs (m_j, s_j) = (8389, 9), (5243, 5), (3277, 1),
// (32768, 1) are exact for every v < 10^4 (all were checked), and 4v < 2^16. The digit is
// then t_j − 10 t_(j−1). Half the instructions of two write_eight_digits, which machines
// without SSE2 use (docs/performance.md, "Traces").
void write_sixteen_digits(char* out, u64 x) {
  const u64 high = x / 100000000;
  const __m128i halves = _mm_set_epi64x(static_cast<long long>(x - high * 100000000),
                                        static_cast<long long>(high));
  const __m128i tens_of_thousands =
      _mm_srli_epi64(_mm_mul_epu32(halves, _mm_set1_epi64x(3518437209)), 45);
  const __m128i rest =
      _mm_sub_epi64(halves, _mm_mul_epu32(tens_of_thousands, _mm_set1_epi64x(10000)));
  // a b c d in 32-bit lanes, then in 16-bit lanes (twice) and times 4
  const __m128i groups = _mm_or_si128(tens_of_thousands, _mm_slli_epi64(rest, 32));
  const __m128i fours = _mm_slli_epi16(_mm_packs_epi32(groups, groups), 2);
  const __m128i pairs = _mm_unpacklo_epi16(fours, fours);  // a a b b c c d d
  const __m128i divide = _mm_setr_epi16(8389, 5243, 3277, -32768, 8389, 5243, 3277, -32768);
  const __m128i shift = _mm_setr_epi16(128, 2048, -32768, -32768, 128, 2048, -32768, -32768);
  const auto digits = [&](__m128i lanes) {  // the eight digits of two groups
    const __m128i t = _mm_mulhi_epu16(_mm_mulhi_epu16(lanes, divide), shift);
    return _mm_sub_epi16(t, _mm_mullo_epi16(_mm_slli_epi64(t, 16), _mm_set1_epi16(10)));
  };
  const __m128i bytes = _mm_packus_epi16(digits(_mm_unpacklo_epi32(pairs, pairs)),
                                         digits(_mm_unpackhi_epi32(pairs, pairs)));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_add_epi8(bytes, _mm_set1_epi8('0')));
}
#else
void write_sixteen_digits(char* out, u64 x) {
  const u64 high = x / 100000000;
  write_eight_digits(out, static_cast<std::uint32_t>(high));
  write_eight_digits(out + 8, static_cast<std::uint32_t>(x - high * 100000000));
}
#endif

// The decimal digits of a number, made sixteen at a time into a buffer with room after them,
// so that they go to their places in copies of one constant size (a few moves, not a call).
class DigitText {
 public:
  static constexpr int block = 24;  // characters a copy writes: room the destination must have

  // The last n ≤ 24 digits of d (zeros before it if n is more than its digits).
  DigitText(u64 d, int n) : n_(n) {
    constexpr u64 ten_to_16 = 10000000000000000u;
    const u64 top = d / ten_to_16;  // the digits before the last sixteen
    write_sixteen_digits(text_ + 16, d - top * ten_to_16);
    if (n > 17) {  // only a whole number past 10^17
      write_eight_digits(text_ + 8, static_cast<std::uint32_t>(top));
    } else {  // a double's seventeenth digit (a zero no copy takes when n < 17: no branch on
      text_[15] = static_cast<char>('0' + top);  // 16 or 17 digits, which is a coin toss)
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
[[gnu::noinline, gnu::cold]] char* write_whole_digits(char* out, u64 c, int q) {
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
// is printf's %f. The lengths compared: fixed n + 1 ("12.5"), 2 − e ("0.001", e < 0 the
// exponent of the last digit) or n + e ("250"); scientific n + 5 ("1.5e-03"), n + 4 for one
// digit ("1e-03"), one more past 10^±99. The cases are told apart by branches that a trace's
// records make predictable, most often the first two.
// `out` has room for 42 characters (digits.copy after 17 digits and a point).
char* write_decimal(char* out, Decimal d, u64 c, int q, bool float_form) {
  const int n = digit_count(d.digits);
  const DigitText digits(d.digits, n);
  const int point = n + d.exponent;  // digits before the decimal point
  if (d.exponent < 0) {
    if (point > 0) {  // "12.5": never longer than scientific
      digits.copy(out);
      digits.copy(out + point + 1, point);
      out[point] = '.';
      return out + n + 1;
    }
    if (point >= (n > 1 ? -3 : -2)) {  // "0.001": 2 − e ≤ n + 5 (n + 4)
      std::memcpy(out, "0.000", 5);
      digits.copy(out + 2 - point);
      return out + 2 - d.exponent;
    }
  } else if (d.exponent <= (n > 1 ? 5 : 4)) {  // "250": n + e ≤ n + 5 (n + 4)
    if (q > 0) {
      out = write_whole_digits(out, c, q);
    } else {
      digits.copy(out);
      std::memset(out + n, '0', static_cast<std::size_t>(d.exponent));
      out += point;
    }
    return float_form ? point_zero(out) : out;
  }
  const int exponent10 = point - 1;  // of the first digit
  const int magnitude = exponent10 < 0 ? -exponent10 : exponent10;
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
  *first = '-';  // kept for a negative x (without a branch: the sign is a coin toss)
  first += bits >> 63;
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
