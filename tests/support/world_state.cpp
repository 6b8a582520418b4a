#include "support/world_state.h"

namespace lamina {

std::vector<unsigned char> state_bytes(const World& world) {
  std::vector<unsigned char> bytes;
  const auto append = [&bytes](const double* values, int count) {
    const auto* first = reinterpret_cast<const unsigned char*>(values);
    bytes.insert(bytes.end(), first, first + count * sizeof(double));
  };
  for (const RigidBody& b : world.bodies()) {
    append(b.x.data(), 3);
    append(b.q.coeffs().data(), 4);
    append(b.v.data(), 3);
    append(b.angular_velocity.data(), 3);
  }
  return bytes;
}

}  // namespace lamina
