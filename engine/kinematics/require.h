// How every stage refuses bad input: one line, thrown as std::invalid_argument where the object
// is created (input is validated once, at the boundary; internal invariants are asserts).
#pragma once

#include <string>

namespace lamina {

// Throws std::invalid_argument(message) unless ok. The message names what was refused and why,
// e.g. "rigid body: position is not finite".
void require(bool ok, const std::string& message);

// The rule for every size, mass and length: finite and > 0. Throws
// std::invalid_argument("<what> must be finite and positive, got <value>") otherwise.
void require_positive(double value, const std::string& what);

}  // namespace lamina
