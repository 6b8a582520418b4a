// The pyramid run by Lamina and by Box2D 2.4.1 from the same Scene, measured alike; and
// issue 20's pyramid of hexagons, run and measured the same way.
//
//   scene     boxes: pyramid_scene(base): boxes of half extents 0.5 placed touching, a static
//             ground box, friction 0.6, Δt = 1/60 (engine/scene/builtin_scenes.cpp)
//             hexagons: builtin_scene("hexagon-pyramid:N"): regular hexagons of circumradius
//             0.5 m as a honeycomb, each row in the gaps of the row below, N(N + 1)/2 of them
//             (convex polygons: Lamina's narrow phase takes them through GJK and EPA)
//   Box2D     8 velocity / 3 position iterations, continuous collision off, sleeping off
//   time      mean CPU time of the thread per step over the 500 steps after the first (CPU
//             time, not wall-clock: other processes on the machine do not count)
//   standing  after 10 s (600 steps): the apex within 0.2 m of its start and no body moved more
//             than 0.1 m sideways (issue 8's bar, for either shape)
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "contact/step_times.h"
#include "scene/scene.h"

namespace lamina {

inline constexpr int timed_steps = 500;     // steps timed, after the first
inline constexpr int standing_steps = 600;  // 10 s at Δt = 1/60
inline constexpr double apex_bar = 0.2;     // m, the apex's largest distance from its start
inline constexpr double sideways_bar = 0.1; // m, any box's largest sideways displacement

// What the pyramid is built of.
enum class PyramidShape { boxes, hexagons };

// "boxes" or "hexagons", for tables and file names.
std::string shape_name(PyramidShape shape);

// The pyramid of that shape with `base` bodies in its base (the apex is the scene's last body).
Scene pyramid_of(PyramidShape shape, int base);

struct PyramidRun {
  int bodies = 0;                 // dynamic bodies: the boxes or hexagons
  double ms_per_step = 0.0;       // mean CPU time per step, in ms
  double wall_ms_per_step = 0.0;  // the same in wall-clock time, in ms
  int contact_points = 0;         // at the end of the timed steps
  int velocity_rows = 0;          // rows of the velocity solve: contact and friction rows
  int position_rows = 0;          // rows of the position solve (split impulse / Box2D's)
  int velocity_iterations = 0;    // sweeps of the velocity solve
  int position_iterations = 0;    // sweeps of the position solve
  double apex_shift = 0.0;        // |apex(10 s) − apex(0)|, in m
  double largest_sideways = 0.0;  // max over bodies of |x(10 s) − x(0)|, in m
  StepTimes phases;               // Lamina's: each phase's wall-clock time over the timed steps

  bool standing() const { return apex_shift <= apex_bar && largest_sideways <= sideways_bar; }
  // The step's time spread over every row of every sweep, in µs: linear growth keeps it flat.
  double us_per_row_sweep() const;
};

// Lamina (World) with the given PGS sweeps per step and the method `solver` (`pgs`, the text's
// PGS with Lamina's additions, or `islands`, the default), on `threads` threads
// (WorldSettings::threads); position sweeps stay 3.
PyramidRun run_lamina_pyramid(PyramidShape shape, int base, int iterations,
                              const std::string& solver = "pgs", int threads = 1);
// Box2D 2.4.1 at 8 velocity / 3 position iterations.
PyramidRun run_box2d_pyramid(PyramidShape shape, int base);

// One run of any engine, measured alike: a first step, the timed steps, the rest of 10 s, and
// the standing check. `where` gives every body's centre (x, y) in the Scene's order; `count_rows`
// fills in the run's contact points, rows and sweeps after the timed steps.
using Positions = std::vector<std::array<double, 2>>;
PyramidRun measure_pyramid_run(const Scene& scene, const std::function<void()>& step,
                               const std::function<Positions()>& where,
                               const std::function<void(PyramidRun&)>& count_rows);

// PGS sweeps to reach ‖W‖ ≤ r ‖W(λ = 0)‖ on the velocity MLCP of the resting pyramid for a few
// residuals r, starting from the contact cache's λ (warm) and from zero (cold), averaged over
// some steps; a start that does not get there within max_sweeps counts max_sweeps.
struct WarmStartRun {
  int base = 0;                      // pyramid base
  int first_step = 0;                // the steps measured: first_step .. first_step + steps − 1
  int steps = 0;
  int max_sweeps = 0;                // the most sweeps tried
  std::vector<double> reductions;    // the residuals r asked for
  std::vector<double> warm_sweeps;   // mean sweeps from the cached λ, per r
  std::vector<double> cold_sweeps;   // mean sweeps from zero, per r
  double warm_residual_10 = 0.0;     // mean ‖W‖ / ‖W(0)‖ after 10 sweeps from the cached λ
  double cold_residual_10 = 0.0;     // the same from zero
};
WarmStartRun measure_warm_start(int base, int first_step, int steps,
                                const std::vector<double>& reductions, int max_sweeps);

}  // namespace lamina
