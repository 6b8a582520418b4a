// A World's state as bytes, for the tests that compare two runs bit for bit (determinism,
// threads): equal bytes, equal bits (−0 and +0, and NaNs, told apart).
#pragma once

#include <vector>

#include "contact/world.h"

namespace lamina {

// The raw bytes of every body's x, q (x, y, z, w), v and ω, in body order.
std::vector<unsigned char> state_bytes(const World& world);

}  // namespace lamina
