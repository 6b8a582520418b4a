#include "constraints/step_settings.h"

#include <cmath>
#include <string>

#include "kinematics/require.h"

namespace lamina {

void validate(const StepSettings& s) {
  require(s.gravity.allFinite() && s.gravity.z() == 0.0,
          "settings: gravity must be finite and in the plane");
  require_positive(s.dt, "settings: dt");
  require(std::isfinite(s.beta) && s.beta >= 0.0 && s.beta <= 1.0,
          "settings: beta must be in [0, 1], got " + std::to_string(s.beta));
  // 0 sweeps is allowed: λ stays at its warm start (scene_limits.h)
  require(s.iterations >= 0, "settings: iterations must be ≥ 0, got " + std::to_string(s.iterations));
}

}  // namespace lamina
