// What must hold of every valid scene, step after step, whatever its shapes, joints and solver:
// the physics fuzzer's invariants (tests/fuzz/physics_fuzzer.cpp, tests/test_physics_invariants.cpp,
// docs/reliability.md). A scene from scene_generator.h is stepped and checked after every step:
//
//   finite      every body's x, q, v, ω finite
//   planar      x_z, v_z, ω_x, ω_y and q's x, y parts exactly 0 (the 3D core must not leak)
//   bounds      for the solvers whose MLCP has them (all but soft-step): each contact's
//               λ_n ≥ 0 and its friction |λ_t| ≤ μ λ_n, μ = √(μ1 μ2) from the scene, to
//               round-off (1e-9 of the step's force scale — its largest λ, or the largest
//               |η_i|/d_i, the force that would stop a row alone — + 1e-9 N, below which
//               Lemke's checked answer is round-off; 1e-6 of it for exact and islands, whose
//               pivots lose digits on the wide kind's ill-conditioned MLCPs)
//   energy      passive scenes (no restitution, no initial velocity, no joints): E(t) − E(0)
//               at most what undoing penetration may add (below)
//   resting     a body placed at rest on the ground settles: over its run it moves up at most
//               creep_distance, sinks at most the slop (what split impulse leaves) and
//               creep_distance more, moves sideways at most creep_distance or half its face
//               and turns at most creep_angle or its tipping angle atan(face/2 ÷ height) (it
//               may rock on its face, not leave it) — the text's method and soft-step at most
//               corner_first_distance (sideways and up) and corner_first_angle: they take a flat
//               face's first contact at one corner (the text's literal deepest point, Fig 4-2;
//               soft-step like Box2D v3's clipping, TieRule::midpoint_first) and tip onto it
//               before the cache holds the other — and over the second half of its run it
//               moves at most a tenth of that (it settles; it does not creep)
//   exact       on an island's velocity MLCP with independent rows (J B of full rank), PGS run to
//               convergence and the exact solution (Lemke) agree on λ
//
// The energy bound. In a passive scene with inelastic contacts, friction and an exactly solved
// velocity step only remove energy, and the integrator (eq. 2-1..2-8, symplectic Euler) loses
// ½ m g² Δt² per step in free fall. Energy enters only where penetration is undone: split impulse
// moves the bodies apart, Baumgarte's and the soft step's bias give them the velocity to do so.
// Undoing a penetration d beyond the slop lifts the bodies above that contact by at most d (a
// body rests on a chain of contacts, so by at most the sum over the contacts, D); and a bias
// gives the bodies a velocity to do it — Baumgarte's (the text's method) at most β D/Δt,
// soft-step's at most D/h for its substep h (Box2D v3's bias rate ω/(2ζ + hω) < 1/h) — whose
// kinetic energy ½ M v² can lift them further (past d once v²/2g > d, deep overlaps); split
// impulse moves positions only. So a step adds at most
//   ΔE_k ≤ |g| M D + ½ M (r D)²,  D = Σ_c max(0, d_c − slop),  r = β/Δt, 1/h or 0
// (M the moving bodies' mass), and E(t) − E(0) ≤ Σ_{k<t} ΔE_k.
// The warm start replays last step's λ, about one step's worth of the weight's impulse M g Δt;
// where the points changed (a flat landing gains its second corner, a point moves to the
// corner) it is applied where it no longer balances, and the step's few sweeps leave part of
// the kinetic energy it gives, at most that of the whole impulse, ½ M (|g| Δt)². Contacts are
// inelastic, so that energy is lost again rather than piled up; it is allowed once:
//   E(t) − E(0) ≤ Σ_{k<t} ΔE_k + ½ M (|g| Δt)²
// The bound is checked for every solver, and what the fuzzer found is in docs/reliability.md.
#pragma once

#include <optional>
#include <string>

#include "support/scene_generator.h"

namespace lamina::fuzz {

inline constexpr double creep_distance = 1e-3;  // m, a resting body's largest move over its run
                                                // (beyond the slop, downward)
inline constexpr double creep_angle = 1e-3;     // rad, and its largest turn
// The text's method and soft-step tip a body placed flat onto the corner they found first
// (measured by the fuzzer: a 0.2 m box at Δt = 1/30 moved 3.5 mm and turned 0.054 rad by the
// text's method, 2.1 mm and 0.033 rad by soft-step, then rested).
inline constexpr double corner_first_distance = 2e-2;  // m
inline constexpr double corner_first_angle = 0.1;      // rad

// What the run found: the first invariant broken (empty when none), and what was checked.
struct InvariantReport {
  std::string violation;        // "energy: step 40: ..."; empty when every invariant held
  bool built = false;           // the World was built (false: the engine refused a value)
  long steps = 0;               // steps taken
  long bound_checks = 0;        // contact points whose λ bounds were checked
  double energy_margin = 0.0;   // passive: the least (bound − gain) over the run, in J
  double largest_gain = 0.0;    // passive: the largest E(t) − E(0), in J
  bool compared_exact = false;  // island: PGS and the exact solution were compared
  double exact_difference = 0.0;  // island: max |λ_PGS − λ_exact| / max(1, |λ_exact|∞)
};

// Builds the generated scene's World (its reader's round trip first: the scene must read back
// as itself), steps it and checks the invariants.
InvariantReport check_invariants(const GeneratedScene& generated);

}  // namespace lamina::fuzz
