// The methods a World can step with, chosen by name (`--solver NAME`, a scene's "solver" key),
// each a set of switches of WorldSettings:
//
//   text  the text's method and nothing else: each pair's deepest point (Fig 4-2), the contact
//         cache of Fig 4-2..4-5 keeping a point until it separates by keep_margin, PGS warm
//         started from the cached λ (eq. 3-24), Baumgarte's bias ζ = −β min(C, 0) with no slop
//         (eq. 4-4, 4-5), friction bounded by ±μ λc per point (eq. 3-26), no restitution.
//   pgs   the text's PGS with what Lamina adds (docs/ch4-contact-model.md, "Beyond the text"):
//         split impulse, a 5 mm slop, ties between equally deep vertices broken, cached points
//         re-anchored as they slide, gaps closed within a step, restitution, one friction row
//         per two-point manifold.
#pragma once

#include <string>
#include <vector>

#include "contact/world.h"

namespace lamina {

struct SolverInfo {
  std::string name;       // what --solver and a scene's "solver" take
  std::string departures; // one line: what it is, and what departs from the text
};

// Every method, in a fixed order: `lamina solvers` prints this.
const std::vector<SolverInfo>& solver_list();

// The settings of the named method: `base` with its contact, cache and friction switches set
// and `solver` naming it. Throws std::invalid_argument naming the methods there are for a name
// that is none of them.
WorldSettings with_solver(WorldSettings base, const std::string& name);

}  // namespace lamina
