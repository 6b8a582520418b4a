#include "support/world_state.h"

#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina {

World world_of(const std::string& scene_name, const std::string& solver, int threads,
               int threads_min_bodies) {
  Scene scene = builtin_scene(scene_name);
  scene.solver = solver;
  WorldSettings settings = world_settings(scene);
  settings.threads = threads;
  settings.threads_min_bodies = threads_min_bodies;
  return build_world(scene, settings);
}

std::vector<unsigned char> state_bytes(const World& world) {
  std::vector<unsigned char> bytes;
  const auto append = [&bytes](const double* values, int count) {
    const auto* first = reinterpret_cast<const unsigned char*>(values);
    bytes.insert(bytes.end(), first, first + count * sizeof(double));
  };
  for (const RigidBody& b : world.bodies()) {
    append(b.x.data(), 3);
    append(b.q.coeffs().data(), 4);
    append(b.v.data(), 3);
    append(b.angular_velocity.data(), 3);
  }
  return bytes;
}

}  // namespace lamina
