// Step k solved a second time by the text's own Projected Gauss-Seidel (constraints/text_pgs.h),
// for --explain: the text's arrays as its pseudo-code makes them — Jsp, Jmap, Convert's Bsp, d,
// η by Multiply, a = B λ by TransposeMultiply — and λ after every sweep, beside the answer of
// the packed PgsSolver that the step used (the same numbers, to round-off).
#pragma once

#include <string>

#include "app/harness/explanation.h"
#include "ch3/constrained_system.h"

namespace lamina::ch3 {

// The text's PGS on step k of the system, from the same λ_exp and for as many sweeps.
tutorial::Section text_pgs_section(const System& s, const std::string& title);

}  // namespace lamina::ch3
