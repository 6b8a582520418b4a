#include "app/cli/work_limits.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/cli/exit_codes.h"
#include "contact/broad_phase.h"
#include "scene/scene_world.h"
#include "scene/shortest_number.h"

namespace lamina::cli {
namespace {

// "5e+07": a count as the messages write limits.
std::string count(double value) { return shortest_number(value); }

[[noreturn]] void refuse(const std::string& origin, const std::string& what, double limit,
                         const std::string& cost) {
  throw InputError(origin + ": " + what + ", more than the " + count(limit) +
                   " a run takes unless asked (" + cost + "); give --allow-large to run it anyway");
}

// The broad phase's candidate pairs at t = 0 with a moving body in them: every pair whose
// bounding boxes overlap (contact/broad_phase.h), of the bodies where the scene places them.
long candidate_pairs(const Scene& scene) {
  std::vector<Aabb> boxes;
  for (const BodyDescription& body : scene.bodies) {
    const PlacedShape placed = place_shape(body);
    Pose2 pose;
    pose.x = placed.centre;
    pose.R << std::cos(body.angle), -std::sin(body.angle), std::sin(body.angle), std::cos(body.angle);
    boxes.push_back(bounding_box(placed.shape, pose));
  }
  SweepMemory memory;
  std::vector<BodyPair> pairs;
  sort_and_sweep(boxes, memory, pairs);
  long moving = 0;
  for (const BodyPair& pair : pairs) {
    if (!scene.bodies[pair.first].is_static || !scene.bodies[pair.second].is_static) ++moving;
  }
  return moving;
}

}  // namespace

void check_work(const Scene& scene, long steps, long frames, const render::FrameSize& size,
                const std::string& origin) {
  // A sweep more than the default 10 costs about a tenth of a step more: sweeps scale the work.
  const double bodies = static_cast<double>(scene.bodies.size());
  const int sweeps = scene.step.iterations;
  const double per_step = bodies * std::max(1.0, sweeps / 10.0);
  if (per_step * steps > max_body_steps) {
    const std::string scaled =
        sweeps > 10 ? " × (" + std::to_string(sweeps) + " sweeps / 10)" : std::string();
    refuse(origin,
           count(bodies) + " bodies × " + std::to_string(steps) + " steps" + scaled + " is " +
               count(per_step * steps) + " body-steps",
           max_body_steps, "a few minutes at 4–10 µs a body-step");
  }
  const long pairs = candidate_pairs(scene);
  if (pairs > max_candidate_pairs) {
    refuse(origin, std::to_string(pairs) + " candidate contact pairs at t = 0 (bodies overlapping)",
           max_candidate_pairs, "about 2 µs a pair every step");
  }
  const double pixels = static_cast<double>(frames) * size.width * size.height;
  if (pixels > max_frame_pixels) {
    refuse(origin,
           std::to_string(frames) + " frames of " + std::to_string(size.width) + "×" +
               std::to_string(size.height) + " is " + count(pixels) + " pixels",
           max_frame_pixels, "about 30 ms a 1280×720 frame");
  }
}

}  // namespace lamina::cli
