// Numbers for frame panels: fixed decimals, so columns line up in the monospaced face.
#pragma once

#include <string>
#include <vector>

#include "kinematics/math_types.h"

namespace lamina::tutorial {

// x with `decimals` digits after the point; never "-0.000".
std::string fixed(double x, int decimals = 3);
// x in scientific notation with two significant digits, e.g. "2.2e-16" (round-off sizes).
std::string scientific(double x);
// "(x, y, z)" with fixed decimals.
std::string fixed(const Vec3& v, int decimals = 3);
// The three rows of a matrix, "[ a  b  c ]", with fixed decimals and aligned columns.
std::vector<std::string> fixed_rows(const Mat3& m, int decimals = 3);
// "1 step", "3 steps": a count and its noun, singular or plural.
std::string counted(long count, const std::string& one, const std::string& many);
// A name as a file name prefix: anything but letters, digits, '.', '_' and '-' becomes '-'
// ("pyramid:5" → "pyramid-5"); an empty name is "scene".
std::string file_prefix(const std::string& name);

}  // namespace lamina::tutorial
