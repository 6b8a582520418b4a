// Chapter 6's lab: a scene of the table (docs/ch6-beyond-the-text.md) run by one method and
// measured after every step, as the table, the bars and the plots read it. Box2D's runs of the
// same scenes (app/reference/box2d_lab.h) are measured by the same LabMeter.
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

#include "kinematics/math_types.h"

namespace lamina {

struct Scene;

struct LabSample {
  double time = 0.0;      // t after the step, in s
  double overlap = 0.0;   // m
  double sideways = 0.0;  // m
  double top = 0.0;       // m
  double stretch = 0.0;   // a fraction
  double energy = 0.0;    // J
};

// A body's pose in the plane: its centre x, y in m and its angle θ about z in rad.
using Pose = Vec3;

struct LabRun {
  std::string scene;               // a built-in scene, NAME or NAME:P
  std::string method;              // beyond/methods.h, or "Box2D 2.4.1"
  std::vector<LabSample> samples;  // after each step, until the end or a divergence
  std::vector<std::vector<Pose>> poses;  // every body's pose at t = 0, then after each step
  bool diverged = false;           // a body's state stopped being finite
  // Over the run:
  double deepest = 0.0;            // the largest overlap, m
  double sideways = 0.0;           // the largest sideways, m
  double top_sway = 0.0;           // the largest |x − x(0)| of the last body, m
  double top_rise = 0.0;           // the last body's y at the end minus at the start, m
  double stretch = 0.0;            // the largest stretch
  double ms_per_step = 0.0;        // the thread's CPU time per step, stepping and measuring
  double rows_per_step = 0.0;      // the mean rows of a step's MLCP (Lamina's runs; 0 for Box2D)
};

// The CPU time this thread has used, in s (a run's cost, untouched by other processes).
double thread_cpu_seconds();

// Measures a run step by step from the bodies' poses, in the scene's body order.
class LabMeter {
 public:
  // The scene, and its bodies' poses at t = 0.
  LabMeter(const Scene& scene, const std::string& method, const std::vector<Pose>& start);
  // After a step: t, every body's pose, the deepest overlap of any contact (m) and the energy.
  void sample(double time, const std::vector<Pose>& poses, double overlap, double energy);
  void diverged() { run_.diverged = true; }
  // The run's CPU time, spread over its steps.
  void cost(double cpu_seconds) { run_.ms_per_step = 1e3 * cpu_seconds / static_cast<double>(run_.samples.size()); }
  // The rows of the steps' MLCPs, summed over the run.
  void rows(double total) { run_.rows_per_step = total / static_cast<double>(run_.samples.size()); }
  const LabRun& run() const { return run_; }

 private:
  std::vector<Pose> start_;
  std::vector<bool> moving_;
  Vec2 pin_ = Vec2::Zero();
  double rest_ = 0.0;  // |ball(0) − pin|, 0 without joints
  LabRun run_;
};

// Runs the scene, by its own method and pitfalls, for `steps` steps of its own Δt (60 Hz for the
// table's scenes). Throws what build_world and with_method throw.
LabRun run_lab(const Scene& scene, int steps);
// The same for a built-in scene (NAME or NAME:P) by the method.
LabRun run_lab(const std::string& scene, const std::string& method, int steps);

}  // namespace lamina
