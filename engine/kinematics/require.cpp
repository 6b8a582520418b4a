#include "kinematics/require.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lamina {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

void require_positive(double value, const std::string& what) {
  if (std::isfinite(value) && value > 0.0) return;
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  throw std::invalid_argument(what + " must be finite and positive, got " + text);
}

}  // namespace lamina
