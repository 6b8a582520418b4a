// `soft-step`: Box2D v3's soft step (Catto, "Solver2D", 2024; box2d v3.1.1's solver.c and
// contact_solver.c), on Lamina's rows (beyond the text).
//
// The step's time Δt is cut into n = 4 substeps of h = Δt / 4. In each:
//   1. velocities   v ← v + h M⁻¹ F_ext
//   2. warm start   v ← v + B P for each row's impulse P (carried from the last substep; the
//                   first from the cache's λ: P = λ h)
//   3. solve        one sweep, joints' rows first, with a soft bias: a row's separation now is
//                   C = C₀ + J Δq (C₀ at t, Δq how far its bodies have moved since), and
//                     C > 0 (a contact's open gap)   bias = C / h, rigid
//                     C ≤ 0                           softened, bias = b C for a joint's row and
//                                   max(s_m b C, −3 m/s / s_m,static) for a contact's (v3's SIMD
//                                   contact solver scales b by s_m):
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
//   6. restitution  a contact that approached faster than 1 m/s gets −e times that speed back
// The λ the World keeps is P / h of the last substep, a force as everywhere in Lamina.
//
// A soft row is a spring-damper, not a constraint: a heavy box sinks into a light one until
// the spring holds it, and the stiffness that keeps substeps stable is what lets it (chapter
// 6's table). Differences from Box2D v3: Lamina's rows are written once per step (a joint's
// anchors do not turn within it; C is updated to first order by J Δq, which Box2D does exactly
// for contacts), a revolute joint's two rows are swept one after the other, not as a 2 × 2
// block, and there are no speculative contact points beyond the cache's.
#pragma once

#include <memory>

#include "contact/step_method.h"

namespace lamina {

constexpr int soft_substeps = 4;  // Box2D v3's default

std::unique_ptr<StepMethod> make_soft_step_method();

}  // namespace lamina
