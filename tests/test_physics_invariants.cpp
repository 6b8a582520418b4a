// The physics fuzzer's invariants (support/physics_invariants.h) on generated scenes
// (support/scene_generator.h): a fixed set of inputs from a seeded generator, and every input
// the fuzzer has kept as a regression (tests/data/fuzz/physics_regressions), so that the main
// test run and the sanitizer run check what the fuzzer checks, on the same code.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "support/physics_invariants.h"

using namespace lamina;
using namespace lamina::fuzz;

namespace {

InvariantReport run(const std::vector<std::uint8_t>& input, GeneratedScene* scene_out = nullptr) {
  Bytes bytes(input.data(), input.size());
  const GeneratedScene generated = generate_scene(bytes);
  if (scene_out) *scene_out = generated;
  return check_invariants(generated);
}

}  // namespace

TEST_SUITE("PhysicsInvariants") {
  TEST_CASE("generated scenes of every shape, joint and solver keep every invariant") {
    std::mt19937 rng(21);
    std::uniform_int_distribution<int> byte(0, 255);
    std::map<std::string, int> per_solver;
    int passive = 0, resting = 0, compared = 0;
    long bound_checks = 0;
    double closest_margin = 1e300, largest_difference = 0.0;
    for (int k = 0; k < 320; ++k) {
      std::vector<std::uint8_t> input(200);
      for (std::uint8_t& b : input) b = static_cast<std::uint8_t>(byte(rng));
      GeneratedScene scene;
      const InvariantReport report = run(input, &scene);
      CAPTURE(k);
      CAPTURE(scene.scene.solver);
      CAPTURE(std::string(kind_name(scene.kind)));
      CHECK(report.violation == "");
      CHECK(report.built);
      ++per_solver[scene.scene.solver];
      if (scene.kind == SceneKind::resting) ++resting;
      if (scene.passive && scene.scene.joints.empty() && scene.kind == SceneKind::general) {
        ++passive;
        closest_margin = std::min(closest_margin, report.energy_margin);
      }
      if (report.compared_exact) {
        ++compared;
        largest_difference = std::max(largest_difference, report.exact_difference);
      }
      bound_checks += report.bound_checks;
    }
    MESSAGE("320 scenes: " << passive << " passive general, " << resting << " resting, " << compared
                           << " islands compared with the exact MLCP (largest λ difference "
                           << largest_difference << "), " << bound_checks
                           << " contact points' bounds checked; least energy margin "
                           << closest_margin << " J");
    // The set reaches every invariant: a regression that stopped generating a kind would
    // otherwise pass by checking nothing.
    CHECK(per_solver.size() == 6);
    CHECK(passive >= 20);
    CHECK(resting >= 40);
    CHECK(compared >= 20);
    CHECK(bound_checks >= 10000);
  }

  TEST_CASE("every scene the physics fuzzer found, kept as a regression, keeps every invariant") {
    const std::filesystem::path folder =
        std::filesystem::path(LAMINA_TEST_DATA_DIR) / "fuzz" / "physics_regressions";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      std::ifstream in(entry.path());
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      CAPTURE(entry.path().filename().string());
      CHECK(check_invariants(regression_scene(text, entry.path().string())).violation == "");
      ++files;
    }
    CHECK(files >= 4);
  }
}
