// Numbers as text: the shortest text that reads back to the same double, written as
// std::to_chars writes it, so a trace holds the run's state exactly and a message shows the
// very value it refuses.
#pragma once

#include <string>

namespace lamina {

// x in that form: "0.5", "2", "-0", "1e+06"; a non-finite x as "inf", "-inf" or "nan".
// Messages show numbers so: "must be in [0, 1], got 1.5".
std::string shortest_number(double x);

// Appends x in that form, with ".0" on whole numbers ("2.0", "-0.0"), so that every value of a
// trace reads as a floating-point number in JSON and spreadsheet tools alike.
void append_shortest(std::string& out, double x);

// Room enough for what append_shortest writes: at most 26 characters
// ("-1.7976931348623157e+308" and ".0"), but the writer copies its digits in blocks of 24 and
// needs up to 43 characters of room (shortest_number.cpp), and ".0" after them.
constexpr int shortest_float_length = 48;
// Writes what append_shortest appends at `first`, which has room for shortest_float_length
// characters, and returns the end of it: for writers that buffer text themselves.
char* write_shortest_float(char* first, double x);

}  // namespace lamina
