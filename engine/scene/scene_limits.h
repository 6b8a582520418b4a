// The ranges a scene's numbers must lie in, in one place. The scene reader (scene_json.cpp)
// refuses a value outside its range with one line naming the JSON path and the range;
// docs/scene-format.md lists them; `lamina run`'s --dt, --iterations, --beta and --steps take the
// same ranges. Each range is far wider than a lecture needs. Its ends are where, measured, a
// result stops meaning anything or stops being a finite number; the reason stands beside each.
// tests/test_extreme_scenes.cpp runs scenes at the ends and checks that every state stays
// finite; tests/test_refused_input.cpp checks that a value just past an end is refused. Figures
// measured with the Release build (-O2) on one core.
#pragma once

#include <cmath>

namespace lamina::scene_limits {

template <typename T>
struct Range {
  T low;   // the smallest value allowed
  T high;  // the largest value allowed
};

// Δt, in s. 1e-5: 10⁷ steps (the most a run takes) still cover 100 s. 1: a box placed on the
// ground still rests there, but one dropped from 1.5 m above it passes through the ground in its
// first step, and a five-box stack already falls apart at 0.1 (all finite).
inline constexpr Range<double> dt{1e-5, 1.0};

// PGS sweeps of the velocity MLCP per step. 0 leaves every λ at its warm start, which is 0 from
// the first step on: nothing holds the bodies up, and a box resting on the ground falls through
// it within 90 steps at Δt = 1/60, the split-impulse push-out only slowing it (finite, and the
// lesson of "no solver"). 10000 sweeps of the 210-box pyramid take 0.16 s per step.
inline constexpr Range<int> iterations{0, 10000};

// β of the position bias (eq. 3-14, 4-4): the fraction of the error removed per step.
inline constexpr Range<double> beta{0.0, 1.0};

// Steps `lamina run` takes. 10⁷ steps of the five-box stack take about 40 s.
inline constexpr Range<int> steps{0, 10000000};

// Each component of g, in m/s² (±1000 g; the Sun's surface has 274 m/s²). States stay finite far
// beyond (measured to 1e100 for 600 steps), but a five-box stack at Δt = 1/60 stands at 100 m/s²
// and falls apart at 300; at Δt = 1e-3 it still stands at 1e4.
inline constexpr Range<double> gravity{-1e4, 1e4};

// Each component of a position or joint anchor, in m. The spacing of doubles near 1e6 is
// 1.2e-10 m, below g Δt² = 9.8e-10 m, how far a body at rest falls in a step of the smallest Δt;
// near 1e7 (spacing 1.9e-9 m) that first step rounds away, and at 1e18 a box on the ground can
// no longer turn (measured).
inline constexpr Range<double> coordinate{-1e6, 1e6};

// A body's angle about z, in rad: the same spacing of doubles, 1.2e-10 rad near 1e6. At 1e15 rad
// the angle names an orientation only to within 0.125 rad.
inline constexpr Range<double> angle{-1e6, 1e6};

// An angle limit's lower or upper end θ_L, in rad: the relative angle θ it is compared with is
// measured in (−π, π] (angle_limit.h), so an end beyond ±π would hold always or never.
// AngleLimit itself refuses −π, the one value of this range outside (−π, π].
inline constexpr Range<double> angle_limit{-M_PI, M_PI};

// Each component of an incline's normal N, which InclineConstraint requires to be a unit vector
// (|N| = 1 within 1e-9): a component beyond ±1 is surely a typing error.
inline constexpr Range<double> normal_component{-1.0, 1.0};

// A box's half extents and a circle's radius, in m. 0.02: the two corners of a box's face must
// lie farther apart than the contact cache's merge distance (0.02 m, contact_cache.h), or they
// merge into one contact point and the box cannot rest. Measured on the ground at Δt = 1/60:
// half extents up to 0.01 m still spin at 9 to 145 rad/s after 5 s, 0.011 m comes to rest; 0.02
// gives a margin of 2 and keeps the contact slop (5 mm, a circle sinks 2.7 mm) within a quarter
// of the size. 1e6: as coordinates.
inline constexpr Range<double> size{0.02, 1e6};

// A capsule's length between its caps' centres, in m: at least twice the size floor, the face of
// the smallest box, for the size floor's reason: its two ends must lie well apart beyond the
// contact cache's merge distance (2 cm). Found by the physics fuzzer: a capsule 0.9 mm long
// resting on the ground had its one contact point jump from end to end every step and rolled
// away at 0.6 mm/s; one 2 cm long and 0.46 m round still rocked on its flat after 10 s, where
// 4 cm settles within 0.008 rad (a circle is the shape for length 0). 1e6 as sizes.
inline constexpr Range<double> capsule_length{2.0 * size.low, 1e6};

// The smallest area of a polygon, in m²: the smallest box's, (2 × 0.02 m)², for the reason of
// `size` (a face of the smallest box still holds two contact points apart).
inline constexpr double polygon_area = 4.0 * size.low * size.low;

// Density, in kg/m². Bodies are 1 m deep, so this is the material's kg/m³: from a thousandth
// of air (1.2) to four times osmium (2.26e4). Only mass ratios change the motion, but densities
// of 1e-300 and 1e300 make a box on the ground non-finite in its first step (1/m and m g
// overflow; 1e-100 to 1e100 stay finite). With sizes in range these ends keep every body's m, 1/m,
// I and 1/I within 1e-30..1e30.
inline constexpr Range<double> density{1e-3, 1e5};

// μ; beyond 10 it is surely a typing error.
inline constexpr Range<double> friction{0.0, 10.0};

// e, the fraction of the approach speed returned.
inline constexpr Range<double> restitution{0.0, 1.0};

// Each component of an initial velocity, in m/s: 10 times a rifle bullet, above orbital speed.
// Lamina has no continuous collision detection: at the smallest Δt (1e-5 s) a box at 1e4 m/s
// still stops on a 0.2 m thick wall, at 1e5 m/s it passes through (measured), and so it does at
// any Δt. At Δt = 1/60 a box falling at 80 m/s already passes through the 1 m thick ground.
inline constexpr Range<double> speed{-1e4, 1e4};

// An initial angular velocity about z, in rad/s (about 95,000 rpm). Eq. 2-6 turns a body by
// 2 atan(ω Δt / 2) per step where it should turn by ω Δt: ω Δt = 0.1, this bound at the smallest
// Δt, turns 0.08 % slow; ω Δt = 1, 7 % slow.
inline constexpr Range<double> angular_speed{-1e4, 1e4};

}  // namespace lamina::scene_limits
