// A World's state as bytes, for the tests that compare two runs bit for bit (determinism,
// threads): equal bytes, equal bits (−0 and +0, and NaNs, told apart); and the World of a
// built-in scene on a number of threads that those tests step.
#pragma once

#include <string>
#include <vector>

#include "contact/world.h"

namespace lamina {

// The built-in scene `scene_name` stepped by `solver` on `threads` threads, from
// `threads_min_bodies` bodies (0: however small the scene, on the threads under test).
World world_of(const std::string& scene_name, const std::string& solver, int threads,
               int threads_min_bodies = 0);

// The raw bytes of every body's x, q (x, y, z, w), v and ω, in body order.
std::vector<unsigned char> state_bytes(const World& world);

}  // namespace lamina
