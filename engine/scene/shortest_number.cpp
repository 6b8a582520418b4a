#include "scene/shortest_number.h"

#include <algorithm>
#include <charconv>

namespace lamina {
namespace {

// Room for to_chars: a double takes at most 24 characters ("-2.2250738585072014e-308").
constexpr int shortest_room = shortest_float_length - 2;

// The one formatter of both forms: x written at `first`, which has shortest_room characters;
// returns the end of it.
char* write_shortest(char* first, double x) {
  return std::to_chars(first, first + shortest_room, x).ptr;
}

}  // namespace

std::string shortest_number(double x) {
  char text[shortest_room];
  return std::string(text, write_shortest(text, x));
}

void append_shortest(std::string& out, double x) {
  char text[shortest_float_length];
  out.append(text, write_shortest_float(text, x));
}

char* write_shortest_float(char* first, double x) {
  char* end = write_shortest(first, x);
  // "0.5", "1e+21", "inf" and "nan" read as floating point already; "2" and "-0" would not.
  const auto is_digit_or_sign = [](char c) { return c == '-' || (c >= '0' && c <= '9'); };
  if (std::all_of(first, end, is_digit_or_sign)) {
    *end++ = '.';
    *end++ = '0';
  }
  return end;
}

}  // namespace lamina
