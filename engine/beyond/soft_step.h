// `soft-step`: Box2D v3's soft step (Catto, "Solver2D", 2024; box2d v3.1.1's solver.c,
// contact_solver.c and constraint_graph.c), on Lamina's rows (beyond the text).
//
// The step's time Δt is cut into n = 4 substeps of h = Δt / 4. In each:
//   1. velocities   v ← v + h M⁻¹ F_ext
//   2. warm start   v ← v + B P for each row's impulse P (carried from the last substep; the
//                   first from the cache's λ: P = λ h)
//   3. solve        one sweep in v3's order (below), with a soft bias: a row's separation now is
//                   C (C₀ at t; a contact's point rides on its bodies with its levers r_k fixed
//                   at t, C = C₀ + Σ_k n_k · (Δx_k + R(Δθ_k) r_k − r_k), v3's "anchors"; a
//                   joint's to first order, C₀ + J Δq), and
//                     C > 0 (a contact's open gap)   bias = C / h, rigid
//                     C ≤ 0                           softened, bias = b C for a joint's row and
//                                   max(b C, −3 m/s / s_m,static) for a contact's (v3's
//                                   coloured contacts; its overflow's cap is 3 m/s):
//                     ΔP = −m_eff s_m (J v + bias) − s_i P       (m_eff = 1/d)
//                   where (b, s_m, s_i) come from a spring of frequency f and damping ratio ζ:
//                     ω = 2π f, a₁ = 2ζ + h ω, a₂ = h ω a₁, a₃ = 1/(1 + a₂),
//                     b = ω / a₁, s_m = a₂ a₃, s_i = a₃
//                   contacts f = 30 Hz, ζ = 10 (60 Hz against a static body), joints f = 60 Hz,
//                   ζ = 2 (Box2D v3's defaults, capped at 1/(8h) and 1/(4h)); a contact's P stays
//                   ≥ 0 and a friction row's within ±μ Σ P of its contact rows (eq. 3-26)
//   4. positions    chapter 2's position update by the new v (eq. 2-5, 2-6)
//   5. relax        the sweep of 3 again without the bias, rigid: the push-out leaves no velocity
// and after the last substep
//   6. restitution  a contact that approached faster than 1 m/s and pushed in any sweep of the
//                   step gets −e times that speed back
// The λ the World keeps is P / h of the last substep, a force as everywhere in Lamina.
//
// The order of the sweeps is v3's graph colouring, and it matters: one sweep per substep is
// Gauss-Seidel, and the row swept last wins. v3 gives each joint and each touching pair the
// lowest of 11 colours none of whose rows moves one of its moving bodies, never colour 0 to a
// pair against a static body, the overflow to what finds none; each keeps its colour while it
// lasts; the overflow is swept first, then colour by colour. A box resting on another on the
// ground is so swept top pair first, ground pair last: the ground holds the lower box still and
// the upper pair's spring, seeing the upper box's whole approach speed, damps it. Swept the
// other way round (the World's pair order) the last sweep drags the lower box down with the
// upper one, the upper spring damps little, and a box 1000 times as heavy sinks 64 cm into the
// light one before it stops (v3 itself, its colours so swapped, does the same), where v3 stops
// it at 44 cm.
//
// A soft row is a spring-damper, not a constraint: a heavy box sinks into a light one until
// the spring holds it, and the stiffness that keeps substeps stable is what lets it (chapter
// 6's table). Differences from Box2D v3: Lamina's rows are written once per step (a joint's
// anchors do not turn within it: its C is updated to first order by J Δq), a revolute joint's
// two rows are swept one after the other, not as a 2 × 2 block, a two-point pair has one
// friction row at its middle (contact_rows.h), new pairs take their colours in the World's
// pair order (v3: in the order its contacts began to touch), and the contact points are the
// World's — the text's deepest point plus the cache's (Fig 4-2..4-5), no speculative points —
// where v3 clips a two-point manifold every step. On heavy-on-light:1000 that last difference
// decides: were the first step's one point the middle of the flat face (the other methods'
// tie rule), the pair would hold the middle and one corner, tilt, and sink through; so a World
// stepped by soft-step takes a corner first (TieRule::midpoint_first off, beyond/methods.cpp),
// the cache gains the other corner the next step, and the soft step holds the heavy box as v3
// does, 35 cm deep.
#pragma once

#include <memory>

#include "contact/step_method.h"

namespace lamina {

constexpr int soft_substeps = 4;  // Box2D v3's default

std::unique_ptr<StepMethod> make_soft_step_method();

}  // namespace lamina
