// Classic mistakes put back on purpose, one switch each (`--pitfall NAME`; chapter 6,
// docs/ch6-beyond-the-text.md), so that a class can watch each one break a scene beside the
// engine as it is. Each is read where its code lives, in the stage that owns it; none is on
// unless asked for.
//
//   lambda-b1           chapter 3: TransposeMultiply scales Bsp[i][k] by λ[b1], λ[b2], as the
//                       text's pseudo-code writes, not by λ[i] (docs/the-text.md, chapter 3)
//   no-renormalisation  chapter 2: q(t+Δt) = q + ½ ω̂ q Δt left as the sum, as eq. 2-6 stops
//   clamp-increment     chapter 3: PGS clamps the increment Δ to [λ⁻, λ⁺] instead of the
//                       accumulated λ + Δ (eq. 3-24 bounds λ, not its change)
//   no-warm-start       chapter 4: λ_exp = 0 every step; the cache keeps its points, not their λ
//   crude-friction      chapter 4: each friction row bounded by ±μ m g of the body it holds
//                       (the text's cruder form) instead of ±μ λc (eq. 3-26)
//   baumgarte-no-slop   chapter 4: Baumgarte's bias (eq. 4-4) with no slop, for Lamina's methods
//                       (the text's own method has it already)
#pragma once

#include <string>
#include <vector>

namespace lamina {

enum class Pitfall {
  lambda_b1,
  no_renormalisation,
  clamp_increment,
  no_warm_start,
  crude_friction,
  baumgarte_no_slop
};

// A set of pitfalls; empty is the engine as it is.
struct Pitfalls {
  unsigned bits = 0;

  bool has(Pitfall p) const { return (bits >> static_cast<unsigned>(p)) & 1u; }
  void add(Pitfall p) { bits |= 1u << static_cast<unsigned>(p); }
  bool empty() const { return bits == 0; }
};

struct PitfallInfo {
  Pitfall pitfall;
  std::string name;  // what --pitfall takes
  std::string what;  // one line: the mistake and where it lives
};

// Every pitfall, in a fixed order.
const std::vector<PitfallInfo>& pitfall_list();

// The pitfall of a name; throws std::invalid_argument naming the pitfalls there are.
Pitfall pitfall_named(const std::string& name);
// Its name.
const std::string& pitfall_name(Pitfall p);

}  // namespace lamina
