// The work a `lamina run` may ask for without saying so: a scene or an option that would run for
// many minutes is refused up front, with one line naming the limit and --allow-large, which
// lifts them (docs/lamina-command.md). Measured on this project's 2-core machine (Release):
//
//   body-steps   bodies × steps × max(1, sweeps / 10) ≤ 5e7. A step at the default 10 sweeps
//                costs 4–10 µs per body (the 210-box pyramid 0.8 ms, the 12880-box pyramid:160
//                110 ms), and the sweeps take most of it beyond (pyramid:10 at 10000 sweeps: 50 ms
//                a step, 900 µs per body), so 5e7 is 3 to 8 minutes; 10⁷ steps of the five-box
//                stack (5e7, 40 s) still run.
//   pairs        candidate pairs of the broad phase at t = 0 ≤ 1e5: a pile of n overlapping
//                bodies has n(n−1)/2, each about 2 µs a step with its contact rows (300 discs
//                in one place, 45 000 pairs: 0.1 s a step; 600, 180 000 pairs: 0.32 s), so
//                1e5 pairs is about 0.2 s a step, 2 minutes for 600 steps.
//   pixels       frames × width × height ≤ 1e10 (--frames, --video, --viewer's frames): a
//                1280 × 720 PNG takes about 30 ms, so 1e10 pixels (10 850 such frames) is
//                about 5 minutes of rendering.
#pragma once

#include <string>

#include "render/style.h"
#include "scene/scene.h"

namespace lamina::cli {

inline constexpr double max_body_steps = 5e7;
inline constexpr double max_candidate_pairs = 1e5;
inline constexpr double max_frame_pixels = 1e10;

// Throws InputError, "<origin>: <what> ... give --allow-large to run it anyway", when the run
// asks for more than a limit above; `frames` is how many frames it renders, of `size`.
void check_work(const Scene& scene, long steps, long frames, const render::FrameSize& size,
                const std::string& origin);

}  // namespace lamina::cli
