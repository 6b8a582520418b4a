// The layers a frame can show on top of its bodies, each switched on by name (--overlay).
#pragma once

#include <array>
#include <bitset>
#include <string>
#include <string_view>

namespace lamina::render {

enum class Overlay {
  contacts,    // contact points: new ones as discs, kept ones as diamonds, re-found both
  normals,     // contact normals n
  forces,      // contact forces as arrows scaled by λ (normal and friction)
  velocities,  // body velocities v
  centres,     // centres of mass x
  axes,        // metre grid with ticks
};

inline constexpr std::array<std::string_view, 6> overlay_names{"contacts",   "normals", "forces",
                                                               "velocities", "centres", "axes"};

// A set of overlays.
class Overlays {
 public:
  Overlays() = default;
  Overlays(std::initializer_list<Overlay> list) {
    for (Overlay o : list) set(o);
  }
  static Overlays all() { return Overlays(~0ULL); }

  void set(Overlay o) { bits_.set(static_cast<std::size_t>(o)); }
  bool has(Overlay o) const { return bits_.test(static_cast<std::size_t>(o)); }

  // "velocities,centres", "all" or "none"; throws std::invalid_argument naming a wrong name.
  static Overlays parse(std::string_view list);
  // The comma-separated names, "none" for the empty set.
  std::string to_string() const;

 private:
  explicit Overlays(unsigned long long bits) : bits_(bits) {}
  std::bitset<overlay_names.size()> bits_;
};

}  // namespace lamina::render
