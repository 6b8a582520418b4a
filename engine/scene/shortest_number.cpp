#include "scene/shortest_number.h"

#include <algorithm>
#include <charconv>

namespace lamina {

void append_shortest(std::string& out, double x) {
  char text[32];
  const char* end = std::to_chars(text, text + sizeof text, x).ptr;
  out.append(text, static_cast<std::size_t>(end - text));
  // "0.5", "1e+21", "inf" and "nan" read as floating point already; "2" and "-0" would not.
  const auto is_digit_or_sign = [](char c) { return c == '-' || (c >= '0' && c <= '9'); };
  if (std::all_of(static_cast<const char*>(text), end, is_digit_or_sign)) out += ".0";
}

}  // namespace lamina
