// Numbers as the docs' Markdown tables print them: fixed digits, no "-0.0000".
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Core>

namespace lamina {

inline std::string fixed(double value, int digits = 4) {
  if (std::abs(value) < 0.5 * std::pow(10.0, -digits)) value = 0.0;
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

// "(a, b, …)" with each entry fixed(·, digits).
template <class Vector>
std::string fixed_vector(const Vector& v, int digits = 4) {
  std::string text = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) text += (i > 0 ? ", " : "") + fixed(v[i], digits);
  return text + ")";
}

}  // namespace lamina
