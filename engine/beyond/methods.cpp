#include "beyond/methods.h"

#include "beyond/block_method.h"
#include "beyond/exact_method.h"
#include "beyond/island_method.h"
#include "beyond/soft_step.h"
#include "kinematics/require.h"

namespace lamina {
namespace {

struct Chapter6 {
  SolverInfo info;
  std::unique_ptr<StepMethod> (*make)();
  bool midpoint_first = true;  // the narrow phase's first-contact tie rule (narrow_phase.h)
};

const std::vector<Chapter6>& chapter6() {
  static const std::vector<Chapter6> list = {
      {{"block",
        "pgs with each two-point manifold's contact rows solved together as a 2 × 2 LCP, exactly "
        "(Box2D 2.4's block solver)"},
       make_block_method},
      {{"exact",
        "each island's MLCP solved exactly by Lemke's pivoting, Coulomb friction included (the "
        "text's reference [3]); islands past 240 variables by pgs"},
       make_exact_method},
      {{"soft-step",
        "Box2D v3's soft step: 4 substeps, contact and joint rows softened by a spring (30 Hz "
        "and 60 Hz), a relax sweep without bias, restitution last"},
       make_soft_step_method,
       false},  // a flat first touch starts from a corner, as v3's two clipped points do
      {{"islands",
        "Lamina's own: small islands solved exactly, those with joints in 8 substeps, large ones "
        "by pgs; split impulse, slop and restitution as pgs (the default)"},
       make_island_method},
  };
  return list;
}

}  // namespace

const std::vector<SolverInfo>& method_list() {
  static const std::vector<SolverInfo> list = [] {
    std::vector<SolverInfo> all = solver_list();
    for (const Chapter6& m : chapter6()) all.push_back(m.info);
    return all;
  }();
  return list;
}

WorldSettings with_method(WorldSettings base, const std::string& name) {
  for (const Chapter6& m : chapter6()) {
    if (m.info.name != name) continue;
    WorldSettings settings = with_solver(base, "pgs");
    settings.solver = name;
    settings.method = m.make;
    settings.cache.ties.midpoint_first = m.midpoint_first;
    return settings;
  }
  for (const SolverInfo& s : solver_list()) {
    if (s.name != name) continue;
    WorldSettings settings = with_solver(base, name);
    settings.method = nullptr;
    return settings;
  }
  std::string names;
  for (const SolverInfo& s : method_list()) names += (names.empty() ? "" : ", ") + s.name;
  throw std::invalid_argument("solver: no solver is named \"" + name + "\" (there are: " + names + ")");
}

}  // namespace lamina
