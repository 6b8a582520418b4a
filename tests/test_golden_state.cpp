// Determinism (issue 9): a golden hash of the final state of a few built-in scenes, like Box2D
// v3's determinism test. Each scene runs `golden_steps` steps with its own settings; the hash is
// FNV-1a 64 over the raw bytes of every body's x, q, v and ω, in body order, and must equal the
// value written below.
//
// Why one value holds for every build: every target is compiled with -ffp-contract=off (the
// top-level CMakeLists.txt), so no a·b + c is fused into one rounding where the CPU has FMA;
// doubles are IEEE binary64 in SSE2 registers on x86-64 (no x87 80-bit intermediates); nothing
// is built with -ffast-math; a World's threads (WorldSettings::threads) split its work the
// same way whatever their timing and keep every sum in the one-thread order; and every result
// is kept in vectors in a fixed order (bodies as added, contact pairs sorted by body index),
// none in an unordered container. The same constants pass in the Release build (build/, -O2), in the
// CI's sanitizer build (build-asan/, RelWithDebInfo: -O2 -g, with ASan and UBSan instrumenting
// the code), and in builds at -O0 and -O3 made by hand to check them. They hold for the default
// x86-64 target, as the presets build it: with -march=native (AVX2, AVX-512, FMA) three of the
// six scenes hash differently, since Eigen then works in wider packets and calls fused
// multiply-add intrinsics itself, which -ffp-contract=off does not reach.
// The other half of issue 9's determinism, the same run giving the same trace and the same PNG
// pixels, is checked by tests/cli/builtin_scenes.cmake and tests/test_render_determinism.cpp.
//
// When the engine changes on purpose, the golden values change with it. Regenerate them with
//   LAMINA_PRINT_GOLDEN=1 build/tests/test_golden_state -tc="*golden*"
// which prints the current table ready to paste over `golden` below; check that the sanitizer
// build (`cmake --preset asan`, build-asan/tests/test_golden_state) then passes with the same
// values, and say in the commit why the states changed.
#include <doctest/doctest.h>

#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"
#include "support/world_state.h"

using namespace lamina;

namespace {

constexpr int golden_steps = 300;  // 5 s at Δt = 1/60: landings, resting, swinging

struct Golden {
  const char* scene;   // a built-in scene name
  const char* solver;  // the method it steps with (beyond/methods.h)
  std::uint64_t hash;  // FNV-1a 64 of its state after golden_steps steps
};

// Scenes that between them exercise contacts with friction and the cache (a tilted landing, a
// stack, a pyramid), revolute joints with contacts (the see-saw, the chain) and a distance
// joint (the pendulum); each with `pgs` and with `islands`, the default, whose exact solves
// (Lemke's pivots, an LDLᵀ) and substeps are held to the same bit-for-bit rule. pyramid:10 is
// one island past the exact solve's size, swept by PGS as `pgs` sweeps it: the same bits.
const Golden golden[] = {
    {"box-on-ground-tilted", "pgs", 0xf40b6f38efff4937},
    {"vertical-stack", "pgs", 0xbda9efeaeac88115},
    {"see-saw", "pgs", 0xc74246b0aae186c6},
    {"chain", "pgs", 0xfb2fcc332abcc7ac},
    {"pendulum", "pgs", 0x1d0805d1cef3d99e},
    {"pyramid:10", "pgs", 0x478636405dfc2cfd},
    {"box-on-ground-tilted", "islands", 0xcab5a6561f167131},
    {"vertical-stack", "islands", 0x8857f14a9859dd40},
    {"see-saw", "islands", 0x654e11249e445354},
    {"chain", "islands", 0xb0823dccf35c469d},
    {"pendulum", "islands", 0x6771b31d283077ad},
    {"pyramid:10", "islands", 0x478636405dfc2cfd},
};

// FNV-1a, 64 bits (offset basis and prime from the FNV reference).
std::uint64_t fnv1a64(const std::vector<unsigned char>& bytes) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char byte : bytes) {
    hash ^= byte;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::vector<unsigned char> final_state(Scene scene, const std::string& solver, int threads = 1) {
  scene.solver = solver;
  WorldSettings settings = world_settings(scene);
  settings.threads = threads;
  settings.threads_min_bodies = 0;  // every golden scene's steps on the threads, however small
  World world = build_world(scene, settings);
  for (int step = 0; step < golden_steps; ++step) world.step();
  return state_bytes(world);
}

}  // namespace

TEST_SUITE("Determinism") {
  TEST_CASE("each scene's state after 5 s matches its golden hash, bit for bit") {
    const bool print = std::getenv("LAMINA_PRINT_GOLDEN") != nullptr;
    for (const Golden& expected : golden) {
      const std::string scene = expected.scene, solver = expected.solver;
      CAPTURE(scene);
      CAPTURE(solver);
      const std::uint64_t hash = fnv1a64(final_state(builtin_scene(expected.scene), expected.solver));
      if (print) {
        std::printf("    {\"%s\", \"%s\", 0x%016" PRIx64 "},\n", expected.scene, expected.solver, hash);
      }
      CHECK(hash == expected.hash);  // exact: the whole state, every bit
    }
  }

  TEST_CASE("on 2 and 3 threads each scene keeps its golden hash") {
    // WorldSettings::threads changes how fast a step is taken, never a bit of it
    // (parallel/workers.h; tests/test_pgs_threads.cpp sweeps a pyramid big enough for PGS's
    // threads).
    for (const Golden& expected : golden) {
      for (const int threads : {2, 3}) {
        const std::string scene = expected.scene, solver = expected.solver;
        CAPTURE(scene);
        CAPTURE(solver);
        CAPTURE(threads);
        CHECK(fnv1a64(final_state(builtin_scene(expected.scene), expected.solver, threads)) ==
              expected.hash);
      }
    }
  }

  TEST_CASE("the same scene run twice in one process gives identical bytes") {
    // Identity, stronger than equal hashes: every byte of every body's state.
    for (const Golden& entry : golden) {
      const std::string scene_name = entry.scene, solver = entry.solver;
      CAPTURE(scene_name);
      CAPTURE(solver);
      const Scene scene = builtin_scene(entry.scene);
      CHECK(final_state(scene, entry.solver) == final_state(scene, entry.solver));
    }
  }

  TEST_CASE("moving one box by one ulp changes the hash") {
    // The hash sees the smallest change a double can make: the last box raised by one unit in
    // the last place (std::nextafter), which the contacts then carry into every body it touches.
    for (const std::string solver : {"pgs", "islands"}) {
      for (const char* name : {"box-on-ground-tilted", "vertical-stack", "pyramid:10"}) {
        CAPTURE(solver);
        CAPTURE(name);
        const Scene scene = builtin_scene(name);
        Scene moved = scene;
        double& y = moved.bodies.back().position[1];
        y = std::nextafter(y, INFINITY);
        CHECK(fnv1a64(final_state(moved, solver)) != fnv1a64(final_state(scene, solver)));
      }
    }
  }
}
