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
  std::string phase = {};  // a World step's phase it belongs to (phase_names), empty elsewhere
};

// The phases of World::step in its order (chapter 5's walk-through), as explanations tag their
// sections and the step-through viewer groups them.
inline constexpr const char* phase_names[] = {"forces", "collision", "cache", "rows",
                                              "solve",  "Jᵀλ",       "integration"};

using Explanation = std::vector<Section>;

// Where the explanation sits in the run: step k goes from t = k Δt to t + Δt.
struct StepContext {
  std::string program;     // the executable, e.g. "lamina" or "04_contact_model"
  std::string scene;       // scene name
  long step = 0;           // k, counted from 0
  double time = 0.0;       // t = k Δt, in s, where the step starts
  double time_step = 0.0;  // Δt, in s
};

std::string to_text(const StepContext& context, const Explanation& explanation);
Json to_json(const StepContext& context, const Explanation& explanation);

// JSON values of the engine's types: vectors as arrays, matrices as arrays of rows.
Json json_of(const Vec3& v);
Json json_of(const Mat3& m);
Json json_of(const Quat& q);
Json json_of(const Eigen::VectorXd& v);
Json json_of(const Eigen::MatrixXd& m);

// A row's bounds as text, "[0, +∞)" or "[-2.94, 2.94]" (JSON has no infinity).
std::string bounds_text(double lower, double upper);

}  // namespace lamina::tutorial
