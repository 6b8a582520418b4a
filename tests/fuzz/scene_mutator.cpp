// A structure-aware mutator for scene_fuzzer (libFuzzer's LLVMFuzzerCustomMutator).
//
// Byte mutations of a scene file nearly always break its JSON, so the loader refuses it and the
// World is never stepped. When the input is a JSON document, this mutator changes it as a
// document instead, half of the time: one number becomes an extreme or nearby value (0, −0,
// denormals, 1e±300, the largest double, ±1, an end of a scene range, scaled by a power of two
// or ten, negated), or one element of an array (a body, a joint, a vector component) is copied
// or removed. The result is written back as JSON, so scenes that parse but hold values the
// engine may not survive are reached in one step. Other inputs, and the other half of the time,
// get libFuzzer's own byte mutations.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_limits.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {

using nlohmann::json;

// A scene's values lie at most this deep: bodies[i].shape.vertices[k][c] is at depth 6.
constexpr int max_depth = 6;

// Every number and every array in the document down to max_depth, depth first.
void collect(json& node, int depth, std::vector<json*>& numbers, std::vector<json*>& arrays) {
  if (node.is_number()) numbers.push_back(&node);
  if (node.is_array()) arrays.push_back(&node);
  if (node.is_structured() && depth < max_depth) {
    for (json& child : node) collect(child, depth + 1, numbers, arrays);
  }
}

// The ends of every range of a scene value (scene_limits.h): the corners of what the loader
// accepts, where the engine is most likely to go non-finite.
double range_end(std::mt19937& rng) {
  namespace limits = lamina::scene_limits;
  static const double ends[] = {
      limits::dt.low,            limits::dt.high,
      limits::iterations.low,    limits::iterations.high,
      limits::gravity.low,       limits::gravity.high,
      limits::coordinate.low,    limits::coordinate.high,
      limits::angle.low,         limits::angle.high,
      limits::size.low,          limits::size.high,
      limits::capsule_length.low, limits::capsule_length.high,
      limits::density.low,       limits::density.high,
      limits::friction.low,      limits::friction.high,
      limits::speed.low,         limits::speed.high,
      limits::angular_speed.low, limits::angular_speed.high,
  };
  return ends[std::uniform_int_distribution<std::size_t>(0, std::size(ends) - 1)(rng)];
}

// A value near the limits of what the loader accepts or the engine can hold.
double extreme_or_nearby(double value, std::mt19937& rng) {
  static const double extremes[] = {0.0, -0.0, 1.0, -1.0, 1e-5, 1e-300, -1e-300,
                                    std::numeric_limits<double>::denorm_min(),
                                    std::numeric_limits<double>::min(), 1e9, 1e300, -1e300,
                                    std::numeric_limits<double>::max(),
                                    -std::numeric_limits<double>::max(), M_PI, 1e4, 10001.0};
  switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
    case 0:
      return extremes[std::uniform_int_distribution<std::size_t>(0, std::size(extremes) - 1)(rng)];
    case 1:
      return range_end(rng);
    case 2:
      return std::ldexp(value, std::uniform_int_distribution<int>(-64, 64)(rng));
    case 3:
      return value * std::pow(10.0, std::uniform_int_distribution<int>(-8, 8)(rng));
    default:
      return -value;
  }
}

void mutate_number(json& number, std::mt19937& rng) {
  const double changed = extreme_or_nearby(number.get<double>(), rng);
  // Whole numbers stay whole numbers (iterations, steps) while they fit a long long.
  if (number.is_number_integer() && std::fabs(changed) < 9e18) {
    number = static_cast<long long>(changed) + std::uniform_int_distribution<int>(-1, 1)(rng);
  } else {
    number = changed;
  }
}

// Copies or removes one element; a copied object with a "name" gets a new one (names are unique).
void mutate_array(json& array, std::mt19937& rng) {
  if (array.empty()) return;
  const std::size_t i = std::uniform_int_distribution<std::size_t>(0, array.size() - 1)(rng);
  if (std::uniform_int_distribution<int>(0, 1)(rng) == 0) {
    array.erase(i);
    return;
  }
  json copy = array[i];
  if (copy.is_object() && copy.contains("name") && copy["name"].is_string()) {
    copy["name"] = copy["name"].get<std::string>() + "'" + std::to_string(array.size());
  }
  array.push_back(std::move(copy));
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
  std::mt19937 rng(seed);
  json document = json::parse(data, data + size, nullptr, false);
  if (document.is_discarded() || std::uniform_int_distribution<int>(0, 1)(rng) == 0) {
    return LLVMFuzzerMutate(data, size, max_size);
  }
  std::vector<json*> numbers;
  std::vector<json*> arrays;
  collect(document, 0, numbers, arrays);
  const std::size_t choices = numbers.size() + arrays.size();
  if (choices == 0) return LLVMFuzzerMutate(data, size, max_size);
  const std::size_t pick = std::uniform_int_distribution<std::size_t>(0, choices - 1)(rng);
  if (pick < numbers.size()) {
    mutate_number(*numbers[pick], rng);
  } else {
    mutate_array(*arrays[pick - numbers.size()], rng);
  }
  const std::string text = document.dump();
  if (text.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, text.data(), text.size());
  return text.size();
}
