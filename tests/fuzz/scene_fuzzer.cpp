// libFuzzer target: a scene file through the loader, the World it builds, and its first steps.
//
// Every input is treated as the text of a scene file. The loader must turn anything into either
// a Scene or one SceneError; build_world must either build the World or refuse a value with
// std::invalid_argument; the steps of an accepted scene must then run without a crash, a
// sanitizer report (ASan, UBSan, LeakSanitizer), any other exception escaping, or leaving a
// body's state non-finite. Inputs are
// mutated as JSON documents half of the time (scene_mutator.cpp).
//
// Bounds that keep one execution fast (libFuzzer's -timeout counts per input, run_fuzzer.sh):
// a scene file may ask for up to 10000 PGS iterations and as many bodies as its bytes allow, and
// a pile of n overlapping bodies makes ~n²/2 contact pairs. Such a scene is still parsed and
// built, but is stepped only within max_stepped_bodies and max_stepped_iterations; -max_len in
// run_fuzzer.sh bounds the file itself.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include "scene/scene_json.h"
#include "scene/scene_world.h"

namespace {

constexpr std::size_t max_stepped_bodies = 64;  // ≤ 2016 contact pairs
constexpr int max_stepped_iterations = 1000;    // PGS sweeps per step
// Two steps: the first fills the contact cache, the second re-places its points (eq. 5-12) and
// warm-starts PGS from the cached λ.
constexpr int steps = 2;

// The non-finite switch. The scene reader's ranges (scene/scene_limits.h) are chosen so that no
// accepted scene can leave a body NaN or infinite, so such a state after a step is a bug: it
// aborts, and libFuzzer saves and minimizes the input. LAMINA_FUZZ_ABORT_ON_NON_FINITE=0 only
// counts them and reports the count at exit (for exploring wider ranges).
bool abort_on_non_finite() {
  const char* value = std::getenv("LAMINA_FUZZ_ABORT_ON_NON_FINITE");
  return value == nullptr || std::strcmp(value, "0") != 0;
}

struct NonFiniteCount {
  const bool abort_on_one = abort_on_non_finite();
  long stepped = 0;     // accepted scenes that were stepped
  long non_finite = 0;  // of those, how many ended with a non-finite body state

  ~NonFiniteCount() {
    std::fprintf(stderr,
                 "scene_fuzzer: %ld of %ld stepped scenes ended with a non-finite body state\n",
                 non_finite, stepped);
  }
};

NonFiniteCount non_finite_count;

// The World of an accepted scene, or nothing when the engine refuses one of its values.
std::optional<lamina::World> build(const lamina::Scene& scene) {
  try {
    return lamina::build_world(scene, lamina::world_settings(scene));
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // refused where the World is built: the boundary did its job
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  lamina::Scene scene;
  try {
    scene = lamina::parse_scene(text, "fuzz.json");
  } catch (const lamina::SceneError&) {
    return 0;  // refused with a message: the loader did its job
  }
  std::optional<lamina::World> world = build(scene);
  if (!world) return 0;
  if (scene.bodies.size() > max_stepped_bodies || scene.step.iterations > max_stepped_iterations) {
    return 0;  // parsed and built, too big to step within -timeout
  }

  for (int i = 0; i < steps; ++i) world->step();
  ++non_finite_count.stepped;
  if (world->first_non_finite_body()) {
    ++non_finite_count.non_finite;
    if (non_finite_count.abort_on_one) {
      std::fprintf(stderr, "scene_fuzzer: non-finite body state after %d steps\n", steps);
      std::abort();
    }
  }
  return 0;
}
