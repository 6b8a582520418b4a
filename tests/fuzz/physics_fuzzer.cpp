// libFuzzer target: the physics, not the loader. Every input is turned into a valid scene by a
// grammar (support/scene_generator.h: bodies of every shape, joints of every type, every solver,
// within scene_limits.h) and stepped for a few hundred steps under ASan + UBSan, with the
// invariants of support/physics_invariants.h checked after every step: finite, exactly planar,
// contact and friction λ within their bounds, a passive scene's energy within what undoing
// penetration may add, a resting body staying put, PGS agreeing with the exact MLCP on small
// islands. A broken invariant prints the scene (JSON) and the invariant and aborts, so libFuzzer
// keeps and can minimise the input (run_fuzzer.sh; docs/reliability.md). What it finds is kept
// as a scene in tests/data/fuzz/physics_regressions/ (an input beginning with '{').
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "scene/scene_json.h"
#include "support/physics_invariants.h"

namespace {

// What the run checked, printed at exit (docs/reliability.md quotes it).
struct Totals {
  long scenes = 0, steps = 0, bound_checks = 0, passive = 0, resting = 0, compared = 0;

  ~Totals() {
    std::fprintf(stderr,
                 "physics_fuzzer: %ld scenes, %ld steps, %ld contact points' λ bounds checked, "
                 "%ld passive scenes' energy, %ld resting bodies, %ld islands against the exact "
                 "MLCP\n",
                 scenes, steps, bound_checks, passive, resting, compared);
  }
};

Totals totals;

// An input that begins with '{' and reads as a regression file is that scene (a scene the
// fuzzer found, kept as a scene: scene_generator.h); any other input, a mutated regression file
// too, is bytes for the grammar.
lamina::fuzz::GeneratedScene scene_of(const std::uint8_t* data, std::size_t size) {
  if (size > 0 && data[0] == '{') {
    try {
      return lamina::fuzz::regression_scene(std::string(reinterpret_cast<const char*>(data), size),
                                            "regression");
    } catch (const std::exception&) {
      // not a regression file: bytes for the grammar, as any input
    }
  }
  lamina::fuzz::Bytes bytes(data, size);
  return lamina::fuzz::generate_scene(bytes);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lamina::fuzz::GeneratedScene generated = scene_of(data, size);
  const lamina::fuzz::InvariantReport report = lamina::fuzz::check_invariants(generated);
  ++totals.scenes;
  totals.steps += report.steps;
  totals.bound_checks += report.bound_checks;
  if (generated.passive && generated.scene.joints.empty()) ++totals.passive;
  if (generated.kind == lamina::fuzz::SceneKind::resting) ++totals.resting;
  if (report.compared_exact) ++totals.compared;
  if (!report.violation.empty()) {
    std::fprintf(stderr, "physics_fuzzer: %s scene, solver %s: %s\nthe scene:\n%s\n",
                 lamina::fuzz::kind_name(generated.kind), generated.scene.solver.c_str(),
                 report.violation.c_str(), lamina::scene_to_json(generated.scene).c_str());
    std::abort();
  }
  return 0;
}
