// Valid scenes from bytes, by a grammar: what the physics fuzzer (tests/fuzz/physics_fuzzer.cpp)
// and its ctest (tests/test_physics_invariants.cpp) step. Every byte string makes a scene the
// scene reader accepts (the generator keeps to scene_limits.h and writes only convex,
// counter-clockwise polygons); the bytes choose which one. A string that runs out reads as
// zeros, so short inputs make small scenes and libFuzzer's mutations change a scene a little.
//
// Four kinds, chosen by the first byte:
//   general  up to 8 dynamic bodies of every shape (box, circle, polygon, capsule) above a
//            ground, a static obstacle sometimes, up to 2 joints of every type, every solver,
//            Δt and sweeps; "passive" (no restitution, no initial velocity, no joints) one time
//            in two, for the energy invariant
//   resting  one body placed resting on the ground on a flat side, at rest: it must stay
//   island   one or two dynamic bodies touching the ground or each other, for comparing PGS's λ
//            with the exact MLCP's
//   wide     every value anywhere in scene_limits.h's ranges (Δt, g, sizes, densities, speeds),
//            evenly in the logarithm, for the invariants that must hold whatever the numbers
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace lamina::fuzz {

// Reads the bytes in order; past the end every read is 0.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte();
  // A whole number in [low, high].
  int integer(int low, int high);
  // A number in [low, high], in 65536 steps (two bytes).
  double number(double low, double high);
  // A number in [low, high] (both > 0), evenly spread in its logarithm.
  double log_number(double low, double high);
  // One time in `times` (the next byte ≡ 0 modulo `times`).
  bool one_in(int times) { return byte() % times == 0; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t next_ = 0;
};

enum class SceneKind { general, resting, island, wide };

// The flat side a resting body stands on.
struct RestingFace {
  double length = 0.0;  // along the ground, in m (0: a circle)
  double height = 0.0;  // of the centre of mass above it, in m
};

struct GeneratedScene {
  Scene scene;
  SceneKind kind = SceneKind::general;
  bool passive = false;   // no restitution, no initial velocity, no joints
  int steps = 0;          // how many steps to take
  std::string resting;    // kind resting: the name of the body placed at rest
  RestingFace face;       // kind resting: the side it stands on
};

// The scene the bytes describe.
GeneratedScene generate_scene(Bytes& bytes);

// A scene the fuzzer found, as kept in tests/data/fuzz/physics_regressions/: a JSON object with
// "kind", "passive", "steps", for a resting one "resting" (the body's name) and "face"
// ([length, height] in m), and "scene", the scene file. Kept as scenes, not as the bytes that
// made them, so that they outlive changes to the grammar. Throws std::invalid_argument for a
// file of another form, and SceneError for its scene.
GeneratedScene regression_scene(const std::string& json_text, const std::string& origin);

const char* kind_name(SceneKind kind);

}  // namespace lamina::fuzz
