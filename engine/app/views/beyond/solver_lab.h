// Chapter 6's lab: a scene of the table (docs/ch6-beyond-the-text.md) run by one method and
// measured after every step, as the table, the bars and the plots read it.
//
//   overlap   the deepest contact of the step, −C of eq. 4-1, in m
//   sideways  the largest horizontal |x − x(0)| of any moving body, in m
//   top       the last body's |x − x(0)| (the top box, the apex, the ball), in m
//   stretch   for a scene with joints: |ball − pin| / |ball(0) − pin| − 1, the pin being the
//             first joint's anchor and the ball the last body; 0 otherwise
//   energy    the moving bodies' mechanical energy (contact/world.h), in J
#pragma once

#include <string>
#include <vector>

namespace lamina {

struct LabSample {
  double time = 0.0;      // t after the step, in s
  double overlap = 0.0;   // m
  double sideways = 0.0;  // m
  double top = 0.0;       // m
  double stretch = 0.0;   // a fraction
  double energy = 0.0;    // J
};

struct LabRun {
  std::string scene;               // a built-in scene, NAME or NAME:P
  std::string method;              // beyond/methods.h
  std::vector<LabSample> samples;  // after each step, until the end or a divergence
  bool diverged = false;           // a body's state stopped being finite
  // Over the run:
  double deepest = 0.0;            // the largest overlap, m
  double sideways = 0.0;           // the largest sideways, m
  double top_sway = 0.0;           // the largest |x − x(0)| of the last body, m
  double top_rise = 0.0;           // the last body's y at the end minus at the start, m
  double stretch = 0.0;            // the largest stretch
};

// Runs the built-in scene by the method for `steps` steps of its own Δt (60 Hz for the table's
// scenes). Throws what build_world and with_method throw for a bad name.
LabRun run_lab(const std::string& scene, const std::string& method, int steps);

}  // namespace lamina
