// What the engine computed at one step, in the text's terms: each quantity with its symbol,
// equation number, meaning, value and unit. Printed as text (--explain) or JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kinematics/math_types.h"

namespace lamina::tutorial {

using Json = nlohmann::ordered_json;  // keys stay in the order they are written

struct Quantity {
  std::string symbol;    // as the text writes it, e.g. "v(t+Δt)"
  std::string equation;  // the text's number, e.g. "2-3"; empty when the text has none
  std::string meaning;   // a few words, e.g. "velocity after the step"
  Json value;            // a number, a vector [x, y, z], a matrix [[row], ...] or {w, x, y, z}
  std::string unit;      // SI unit, empty for pure numbers
};

// A group of quantities, e.g. one body or one integrator.
struct Section {
  std::string title;
  std::vector<Quantity> quantities;
};

using Explanation = std::vector<Section>;

// Where the explanation sits in the run.
struct StepContext {
  std::string tutorial;    // executable name
  std::string scene;       // scene name
  long step = 0;           // steps taken since the start
  double time = 0.0;       // t = step Δt, in s
  double time_step = 0.0;  // Δt, in s
};

std::string to_text(const StepContext& context, const Explanation& explanation);
Json to_json(const StepContext& context, const Explanation& explanation);

// JSON values of the engine's types.
Json json_of(const Vec3& v);
Json json_of(const Mat3& m);
Json json_of(const Quat& q);

}  // namespace lamina::tutorial
