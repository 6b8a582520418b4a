#include "motion/pitfalls.h"

#include "kinematics/require.h"

namespace lamina {

const std::vector<PitfallInfo>& pitfall_list() {
  static const std::vector<PitfallInfo> list = {
      {Pitfall::lambda_b1, "lambda-b1",
       "the text's TransposeMultiply: a = B λ scaled by λ[b1], λ[b2] (body indices) instead of λ[i]"},
      {Pitfall::no_renormalisation, "no-renormalisation",
       "eq. 2-6 as the text stops: q + ½ ω̂ q Δt never renormalised, so |q| grows"},
      {Pitfall::clamp_increment, "clamp-increment",
       "PGS clamps the increment Δ to [λ⁻, λ⁺] instead of the accumulated λ + Δ"},
      {Pitfall::no_warm_start, "no-warm-start",
       "λ_exp = 0 every step: the contact cache keeps its points but not their λ"},
      {Pitfall::crude_friction, "crude-friction",
       "friction bounded by ±μ m g per point (the text's cruder form) instead of ±μ λc"},
      {Pitfall::baumgarte_no_slop, "baumgarte-no-slop",
       "Baumgarte's bias β C / Δt with no slop instead of split impulse"},
  };
  return list;
}

Pitfall pitfall_named(const std::string& name) {
  std::string names;
  for (const PitfallInfo& p : pitfall_list()) {
    if (p.name == name) return p.pitfall;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  require(false, "pitfall: none is named \"" + name + "\" (there are: " + names + ")");
  return Pitfall::lambda_b1;
}

const std::string& pitfall_name(Pitfall p) {
  for (const PitfallInfo& info : pitfall_list()) {
    if (info.pitfall == p) return info.name;
  }
  return pitfall_list().front().name;
}

}  // namespace lamina
