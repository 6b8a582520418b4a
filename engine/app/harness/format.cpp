#include "app/harness/format.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace lamina::tutorial {

std::string fixed(double x, int decimals) {
  const double rounded = std::round(x * std::pow(10.0, decimals));
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, rounded == 0.0 ? 0.0 : x);
  return text;
}

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1e", x);
  return text;
}

std::string fixed(const Vec3& v, int decimals) {
  return "(" + fixed(v.x(), decimals) + ", " + fixed(v.y(), decimals) + ", " +
         fixed(v.z(), decimals) + ")";
}

std::vector<std::string> fixed_rows(const Mat3& m, int decimals) {
  std::vector<std::string> rows;
  for (int r = 0; r < 3; ++r) {
    char row[128];
    std::snprintf(row, sizeof row, "[%*s %*s %*s ]", decimals + 4, fixed(m(r, 0), decimals).c_str(),
                  decimals + 4, fixed(m(r, 1), decimals).c_str(), decimals + 4,
                  fixed(m(r, 2), decimals).c_str());
    rows.push_back(row);
  }
  return rows;
}

std::string counted(long count, const std::string& one, const std::string& many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

std::string file_prefix(const std::string& name) {
  std::string prefix = name;
  for (char& c : prefix) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
    if (!plain) c = '-';
  }
  return prefix.empty() ? "scene" : prefix;
}

}  // namespace lamina::tutorial
