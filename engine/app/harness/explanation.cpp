#include "app/harness/explanation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "language/language.h"

namespace lamina::tutorial {
namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x == 0.0 ? 0.0 : x);  // no "-0"
  return text;
}

bool is_matrix(const Json& v) { return v.is_array() && !v.empty() && v[0].is_array(); }

// A matrix as rows "[ a  b  c ]", every column as wide as its widest entry.
std::vector<std::string> matrix_rows(const Json& m) {
  std::size_t width = 0;
  for (const auto& row : m) {
    for (const auto& x : row) width = std::max(width, number(x.get<double>()).size());
  }
  std::vector<std::string> rows;
  for (const auto& row : m) {
    std::string line = "[";
    for (const auto& x : row) {
      const std::string n = number(x.get<double>());
      line += " " + std::string(width - n.size(), ' ') + n;
    }
    rows.push_back(line + " ]");
  }
  return rows;
}

std::string inline_value(const Json& v) {
  if (v.is_number()) return number(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  if (v.is_object()) {  // a quaternion w + (x, y, z)
    return number(v["w"].get<double>()) + " + (" + number(v["x"].get<double>()) + ", " +
           number(v["y"].get<double>()) + ", " + number(v["z"].get<double>()) + ")";
  }
  if (v.is_array()) {
    std::string text = "(";
    for (std::size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + inline_value(v[i]);
    return text + ")";
  }
  return v.dump();
}

void write_quantity(std::ostringstream& out, const Quantity& q) {
  out << "  " << q.symbol;
  if (!q.equation.empty()) out << "  " << fill(tr("[eq. {0}]"), {q.equation});
  out << "  " << q.meaning << "\n";
  const std::string unit = q.unit.empty() ? "" : " " + q.unit;
  if (!is_matrix(q.value)) {
    out << "      = " << inline_value(q.value) << unit << "\n";
    return;
  }
  const std::vector<std::string> rows = matrix_rows(q.value);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    out << (i == 0 ? "      = " : "        ") << rows[i] << (i + 1 == rows.size() ? unit : "")
        << "\n";
  }
}

}  // namespace

std::string to_text(const StepContext& c, const Explanation& explanation) {
  std::ostringstream out;
  out << fill(tr("{0} — {1}, step {2}: t = {3} s → {4} s (Δt = {5} s)"),
              {c.program, c.scene, std::to_string(c.step), number(c.time),
               number(c.time + c.time_step), number(c.time_step)})
      << "\n";
  for (const Section& s : explanation) {
    out << "\n" << s.title << "\n";
    for (const Quantity& q : s.quantities) write_quantity(out, q);
  }
  return out.str();
}

Json to_json(const StepContext& c, const Explanation& explanation) {
  Json sections = Json::array();
  for (const Section& s : explanation) {
    Json quantities = Json::array();
    for (const Quantity& q : s.quantities) {
      quantities.push_back({{"symbol", q.symbol},
                            {"equation", q.equation},
                            {"meaning", q.meaning},
                            {"value", q.value},
                            {"unit", q.unit}});
    }
    Json section = {{"title", s.title}, {"quantities", quantities}};
    if (!s.phase.empty()) section["phase"] = s.phase;
    sections.push_back(std::move(section));
  }
  return {{"program", c.program}, {"scene", c.scene},    {"step", c.step}, {"t", c.time},
          {"dt", c.time_step},    {"sections", sections}};
}

Json json_of(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Json json_of(const Mat3& m) {
  Json rows = Json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2)});
  return rows;
}

Json json_of(const Quat& q) { return {{"w", q.w()}, {"x", q.x()}, {"y", q.y()}, {"z", q.z()}}; }

Json json_of(const Eigen::VectorXd& v) {
  Json values = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) values.push_back(v[i]);
  return values;
}

Json json_of(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) rows.push_back(json_of(Eigen::VectorXd(m.row(r).transpose())));
  return rows;
}

std::string bounds_text(double lower, double upper) {
  auto end = [](double x) { return std::isinf(x) ? std::string(x > 0 ? "+∞" : "−∞") : number(x); };
  return (std::isinf(lower) ? "(" : "[") + end(lower) + ", " + end(upper) + (std::isinf(upper) ? ")" : "]");
}

}  // namespace lamina::tutorial
