#include "scene/shortest_number.h"

#include <algorithm>
#include <charconv>
#include <string_view>

namespace lamina {
namespace {

// The one formatter of both forms: x written into `text`, which it returns a view of.
std::string_view write_shortest(char (&text)[32], double x) {
  const char* end = std::to_chars(text, text + sizeof text, x).ptr;
  return {text, static_cast<std::size_t>(end - text)};
}

}  // namespace

std::string shortest_number(double x) {
  char text[32];
  return std::string(write_shortest(text, x));
}

void append_shortest(std::string& out, double x) {
  char text[32];
  const std::string_view shortest = write_shortest(text, x);
  out += shortest;
  // "0.5", "1e+21", "inf" and "nan" read as floating point already; "2" and "-0" would not.
  const auto is_digit_or_sign = [](char c) { return c == '-' || (c >= '0' && c <= '9'); };
  if (std::all_of(shortest.begin(), shortest.end(), is_digit_or_sign)) out += ".0";
}

}  // namespace lamina
