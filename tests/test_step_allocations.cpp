// A steady World step allocates nothing: every buffer of the step is kept from step to step
// (docs/performance.md). Checked for the World's own step, `pgs`, for chapter 6's `islands`, the
// default (its island lists, Lemke's tableau, the LDLᵀ of a joint chain), and for soft-step.
// Counted by replacing the global operator new/delete and, on glibc, the malloc family too
// (Eigen's dynamic vectors call std::malloc, not operator new).
#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace {

std::atomic<long> allocations{0};  // operator new and malloc-family calls since the start

void* counted(void* memory) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return memory;
}

void* allocate(std::size_t size) {
  void* memory = std::malloc(size == 0 ? 1 : size);
  if (memory == nullptr) throw std::bad_alloc();
  return counted(memory);
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }

// AddressSanitizer brings its own malloc; replacing it there would hide memory from ASan.
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#define LAMINA_COUNTS_MALLOC 1
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* memory, std::size_t size);
void __libc_free(void* memory);

void* malloc(std::size_t size) noexcept { return counted(__libc_malloc(size)); }
void* calloc(std::size_t count, std::size_t size) noexcept {
  return counted(__libc_calloc(count, size));
}
void* realloc(void* memory, std::size_t size) noexcept {
  return counted(__libc_realloc(memory, size));
}
void free(void* memory) noexcept { __libc_free(memory); }
}
#endif

using namespace lamina;

namespace {

// Allocations made by 100 steps of a built-in scene, after `settle` steps to settle and grow
// every buffer, by the method `solver`.
long allocations_in_steady_steps(const std::string& scene_name, const std::string& solver = "pgs",
                                 int settle = 100) {
  Scene scene = builtin_scene(scene_name);
  scene.solver = solver;
  World world = build_world(scene, world_settings(scene));
  for (int step = 0; step < settle; ++step) world.step();
  const long before = allocations.load();
  for (int step = 0; step < 100; ++step) world.step();
  return allocations.load() - before;
}

}  // namespace

TEST_SUITE("StepAllocations") {
  TEST_CASE("the counter sees operator new, and malloc where it is replaced") {
    static void* volatile kept;  // volatile: the compiler may not drop the allocations below
    const long before = allocations.load();
    kept = new int(1);
    delete static_cast<int*>(kept);
#ifdef LAMINA_COUNTS_MALLOC
    kept = std::malloc(16);
    std::free(kept);
    CHECK(allocations.load() - before >= 2);
#else
    MESSAGE("AddressSanitizer build: malloc is ASan's, only operator new is counted "
            "(Eigen's vectors allocate with malloc and go unseen here)");
    CHECK(allocations.load() - before >= 1);
#endif
  }

  TEST_CASE("a resting stack of five boxes steps without allocating") {
    // exact: a buffer that grows mid-run would show as at least one allocation
    CHECK(allocations_in_steady_steps("vertical-stack") == 0);
  }

  TEST_CASE("a resting 20-row pyramid steps without allocating") {
    CHECK(allocations_in_steady_steps("pyramid") == 0);
  }

  TEST_CASE("a bridge of pinned planks under a box steps without allocating (joints' rows too)") {
    CHECK(allocations_in_steady_steps("bridge") == 0);
  }

  TEST_CASE("a honeycomb pyramid of hexagons and a capsule pile step without allocating (GJK, EPA)") {
    CHECK(allocations_in_steady_steps("hexagon-pyramid") == 0);
    CHECK(allocations_in_steady_steps("capsule-pile") == 0);
  }

  TEST_CASE("islands, the default, steps without allocating: its island lists, PGS and exact solves") {
    // vertical-stack: one island solved by Lemke; pyramid: one island of 1100 rows, swept by
    // PGS; capsule-pile and hexagon-pyramid: islands of several sizes, each solved by Lemke
    // with the memory of its own (one workspace for all would grow and shrink between them)
    CHECK(allocations_in_steady_steps("vertical-stack", "islands") == 0);
    CHECK(allocations_in_steady_steps("pyramid", "islands") == 0);
    // the capsule pile by islands comes to rest at step 119 (its last contact of a gap let go,
    // the islands split one last time: measured in its trace), so it settles for 150
    CHECK(allocations_in_steady_steps("capsule-pile", "islands", 150) == 0);
    CHECK(allocations_in_steady_steps("hexagon-pyramid", "islands") == 0);
    // joints: substepped, their rows written again each substep; the pendulum's and the ball and
    // chain's by LDLᵀ (rows of equalities only), the angle limit's by Lemke. Scenes whose islands
    // change size from step to step (a contact made for the first time, the bouncing bridge)
    // allocate when an island outgrows the memory it had.
    CHECK(allocations_in_steady_steps("pendulum", "islands") == 0);
    CHECK(allocations_in_steady_steps("ball-and-chain", "islands") == 0);
    CHECK(allocations_in_steady_steps("angle-limit", "islands") == 0);
  }

  TEST_CASE("soft-step's resting pyramid and bridge step without allocating (its colouring too)") {
    // soft-step keeps each pair's colour from step to step (Box2D v3's graph colouring): the
    // colours live in vectors kept by the method, walked in pair order, not a map rebuilt each step
    CHECK(allocations_in_steady_steps("pyramid", "soft-step") == 0);
    CHECK(allocations_in_steady_steps("bridge", "soft-step") == 0);
  }
}
