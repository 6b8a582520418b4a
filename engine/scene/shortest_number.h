// Numbers in traces: the shortest text that reads back to the same double (std::to_chars), so a
// trace holds the run's state exactly. Whole numbers keep a ".0" ("2.0", "-0.0"), so that every
// value reads as a floating-point number in JSON and spreadsheet tools alike.
#pragma once

#include <string>

namespace lamina {

// Appends x in that form; a non-finite x as "inf", "-inf" or "nan".
void append_shortest(std::string& out, double x);

}  // namespace lamina
