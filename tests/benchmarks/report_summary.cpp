#include "benchmarks/report_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lamina::report {

std::optional<Summary> summary(const Measurements& m, const RunKey& key) {
  const auto it = m.runs.find(key);
  if (it == m.runs.end() || it->second.empty()) return std::nullopt;
  std::vector<double> ms;
  std::vector<double> wall;
  for (const PyramidRun& run : it->second) {
    ms.push_back(run.ms_per_step);
    wall.push_back(run.wall_ms_per_step);
  }
  Summary s{static_cast<int>(ms.size()), median(ms), *std::min_element(ms.begin(), ms.end()),
            *std::max_element(ms.begin(), ms.end()), median(wall), it->second.front()};
  for (const PyramidRun& run : it->second) {
    if (std::abs(run.ms_per_step - s.ms) < std::abs(s.run.ms_per_step - s.ms)) s.run = run;
  }
  return s;
}

RunKey box2d_key(int base) { return {"Box2D", base, box2d_iterations}; }

RunKey islands_key(int base) { return {"Lamina islands", base, recommended_iterations}; }
RunKey v3_key(int base) { return {"Box2D v3", base, v3_substeps}; }

RunKey hexagon_key(const std::string& engine, int base) {
  return {engine, base, box2d_iterations, PyramidShape::hexagons};
}

std::vector<int> bases(const Measurements& m, PyramidShape shape) {
  std::vector<int> out;
  for (const auto& [key, runs] : m.runs) {
    if (key.shape != shape) continue;
    if (std::find(out.begin(), out.end(), key.base) == out.end()) out.push_back(key.base);
  }
  std::sort(out.begin(), out.end());
  return out;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

std::string with_range(double middle, double low, double high, int digits,
                       const std::string& unit) {
  return fixed(middle, digits) + unit + " (" + fixed(low, digits) + "–" + fixed(high, digits) + ")";
}

std::string median_and_range(const std::vector<double>& values, int digits,
                             const std::string& unit) {
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  return with_range(median(values), *low, *high, digits, unit);
}

}  // namespace lamina::report
