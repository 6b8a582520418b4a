#include "app/views/beyond/solver_lab.h"

#include <algorithm>
#include <cmath>

#include "contact/world.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina {

LabRun run_lab(const std::string& scene_name, const std::string& method, int steps) {
  Scene scene = builtin_scene(scene_name);
  scene.solver = method;
  World world = build_world(scene, world_settings(scene));
  LabRun run;
  run.scene = scene_name;
  run.method = method;
  const std::vector<RigidBody> start = world.bodies();
  const Vec3& top0 = start.back().x;
  const bool jointed = !scene.joints.empty();
  const Vec3 pin = jointed ? Vec3(scene.joints[0].anchor.x(), scene.joints[0].anchor.y(), 0.0)
                           : Vec3::Zero();
  const double rest = (top0 - pin).norm();
  for (int k = 0; k < steps; ++k) {
    world.step();
    if (first_non_finite_body(world)) {
      run.diverged = true;
      break;
    }
    LabSample s;
    s.time = world.time();
    for (const ContactInfo& c : world.contacts()) s.overlap = std::max(s.overlap, -c.separation);
    const std::vector<RigidBody>& bodies = world.bodies();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (!bodies[b].is_static()) s.sideways = std::max(s.sideways, std::abs(bodies[b].x.x() - start[b].x.x()));
    }
    run.sideways = std::max(run.sideways, s.sideways);
    s.top = (bodies.back().x - top0).norm();
    if (jointed) s.stretch = (bodies.back().x - pin).norm() / rest - 1.0;
    s.energy = mechanical_energy(world);
    run.deepest = std::max(run.deepest, s.overlap);
    run.top_sway = std::max(run.top_sway, std::abs(bodies.back().x.x() - top0.x()));
    run.top_rise = bodies.back().x.y() - top0.y();
    run.stretch = std::max(run.stretch, s.stretch);
    run.samples.push_back(s);
  }
  return run;
}

}  // namespace lamina
