#include "contact/solvers.h"

#include "kinematics/require.h"

namespace lamina {
namespace {

bool is_solver(const std::string& name) {
  for (const SolverInfo& s : solver_list()) {
    if (s.name == name) return true;
  }
  return false;
}

std::string names() {
  std::string list;
  for (const SolverInfo& s : solver_list()) list += (list.empty() ? "" : ", ") + s.name;
  return list;
}

}  // namespace

const std::vector<SolverInfo>& solver_list() {
  static const std::vector<SolverInfo> list = {
      {"text",
       "the text's method and nothing else: deepest point per pair, contact cache, PGS warm "
       "started from it, Baumgarte bias with β and no slop, friction ±μ λc per point, no "
       "restitution"},
      {"pgs",
       "the text's PGS with split impulse, a 5 mm slop, ties broken, cached points re-anchored, "
       "gaps closed, restitution, one friction row per two-point manifold, a pair that barely "
       "moved not collided again"},
  };
  return list;
}

WorldSettings with_solver(WorldSettings settings, const std::string& name) {
  require(is_solver(name), "solver: no solver is named \"" + name + "\" (there are: " + names() + ")");
  settings.solver = name;
  const bool text = name == "text";
  ContactSettings& contact = settings.contact;
  contact.correction = text ? PositionCorrection::baumgarte : PositionCorrection::split_impulse;
  contact.slop = text ? 0.0 : ContactSettings().slop;
  contact.restitution = !text;
  contact.close_gaps = !text;
  contact.friction = text ? FrictionRows::per_point : FrictionRows::per_manifold;
  settings.cache.ties.break_ties = !text;
  settings.cache.reanchor = !text;
  settings.cache.recycle = !text;
  return settings;
}

}  // namespace lamina
