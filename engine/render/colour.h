// Colours of Lamina's lecture style: a light background, dark ink and the Okabe–Ito palette,
// whose eight colours stay distinct for the common forms of colour blindness.
#pragma once

#include <cstdint>

namespace lamina::render {

// An sRGB colour with opacity, 8 bits per channel.
struct Colour {
  std::uint8_t r = 0;    // red
  std::uint8_t g = 0;    // green
  std::uint8_t b = 0;    // blue
  std::uint8_t a = 255;  // opacity: 255 opaque, 0 invisible

  bool operator==(const Colour& o) const { return r == o.r && g == o.g && b == o.b && a == o.a; }
};

// The same colour mixed with white: fraction 1 keeps it, 0 gives white (for body fills).
constexpr Colour tint(Colour c, double fraction) {
  auto mix = [fraction](std::uint8_t v) {
    return static_cast<std::uint8_t>(255.0 - (255.0 - v) * fraction + 0.5);
  };
  return {mix(c.r), mix(c.g), mix(c.b), c.a};
}

// The same colour with another opacity.
constexpr Colour with_alpha(Colour c, std::uint8_t alpha) { return {c.r, c.g, c.b, alpha}; }

namespace palette {
inline constexpr Colour background{251, 251, 248};  // paper white
inline constexpr Colour ink{31, 31, 31};            // outlines, text
inline constexpr Colour grey{120, 120, 120};        // secondary text, reference curves
inline constexpr Colour grid{226, 226, 222};        // metre grid
inline constexpr Colour white{255, 255, 255};
// Okabe–Ito (Okabe & Ito, "Color Universal Design", 2008).
inline constexpr Colour orange{230, 159, 0};
inline constexpr Colour sky_blue{86, 180, 233};
inline constexpr Colour bluish_green{0, 158, 115};
inline constexpr Colour yellow{240, 228, 66};
inline constexpr Colour blue{0, 114, 178};
inline constexpr Colour vermillion{213, 94, 0};
inline constexpr Colour reddish_purple{204, 121, 167};
}  // namespace palette

}  // namespace lamina::render
