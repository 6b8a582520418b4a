#include "app/views/beyond/solver_lab.h"

#include <algorithm>
#include <cmath>
#include <ctime>

#include "contact/world.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina {

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

LabMeter::LabMeter(const Scene& scene, const std::string& method, const std::vector<Pose>& start)
    : start_(start) {
  run_.scene = scene.name;
  run_.method = method;
  run_.poses.push_back(start);
  for (const BodyDescription& b : scene.bodies) moving_.push_back(!b.is_static);
  if (!scene.joints.empty()) {
    pin_ = scene.joints[0].anchor;
    rest_ = (start_.back().head<2>() - pin_).norm();
  }
}

void LabMeter::sample(double time, const std::vector<Pose>& poses, double overlap, double energy) {
  run_.poses.push_back(poses);
  LabSample s;
  s.time = time;
  s.overlap = overlap;
  for (std::size_t b = 0; b < poses.size(); ++b) {
    if (moving_[b]) s.sideways = std::max(s.sideways, std::abs(poses[b].x() - start_[b].x()));
  }
  const Vec2 top = poses.back().head<2>(), top0 = start_.back().head<2>();
  s.top = (top - top0).norm();
  if (rest_ > 0.0) s.stretch = (top - pin_).norm() / rest_ - 1.0;
  s.energy = energy;
  run_.deepest = std::max(run_.deepest, s.overlap);
  run_.sideways = std::max(run_.sideways, s.sideways);
  run_.top_sway = std::max(run_.top_sway, std::abs(top.x() - top0.x()));
  run_.top_rise = top.y() - top0.y();
  run_.stretch = std::max(run_.stretch, s.stretch);
  run_.samples.push_back(s);
}

namespace {

std::vector<Pose> poses_of(const World& world) {
  std::vector<Pose> poses;
  for (const RigidBody& b : world.bodies()) poses.emplace_back(b.x.x(), b.x.y(), planar_angle(b.q));
  return poses;
}

}  // namespace

LabRun run_lab(const std::string& scene_name, const std::string& method, int steps) {
  Scene scene = builtin_scene(scene_name);
  scene.solver = method;
  return run_lab(scene, steps);
}

LabRun run_lab(const Scene& scene, int steps) {
  World world = build_world(scene, world_settings(scene));
  LabMeter meter(scene, scene.solver, poses_of(world));
  const double start = thread_cpu_seconds();
  double rows = 0.0;
  for (int k = 0; k < steps; ++k) {
    world.step();
    for (const ContactPair& pair : world.contact_pairs()) rows += pair.rows.count;
    for (int j = 0; j < world.joint_count(); ++j) rows += world.joint_rows(j).count;
    if (world.first_non_finite_body()) {
      meter.diverged();
      break;
    }
    double overlap = 0.0;
    for (const ContactInfo& c : world.contacts()) overlap = std::max(overlap, -c.separation);
    meter.sample(world.time(), poses_of(world), overlap, mechanical_energy(world));
  }
  meter.cost(thread_cpu_seconds() - start);
  meter.rows(rows);
  return meter.run();
}

}  // namespace lamina
