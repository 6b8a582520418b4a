// Text with FreeType and the fonts of font_set.h (DejaVu, then Nanum Gothic for Hangul): glyphs
// rasterised once into the atlas as a run first needs them, then drawn as pixel-aligned textured
// rectangles (sharp at any MSAA setting).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "render/font_set.h"
#include "render/glyph_atlas.h"
#include "render/mesh.h"

namespace lamina::render {

struct TextStyle {
  Typeface face = Typeface::sans;
  int px = 19;  // em size, in pixels
  Colour colour = palette::ink;
};

// Vertical metrics of a face at a size, in pixels.
struct LineMetrics {
  double ascender;   // baseline to the top of the tallest glyph
  double descender;  // baseline to the bottom of the deepest glyph (positive)
  double height;     // baseline to baseline
};

class Typesetter {
 public:
  // Opens the fonts (FontSet). Throws std::runtime_error naming the Debian package when a font
  // cannot be opened.
  Typesetter();
  ~Typesetter();
  Typesetter(const Typesetter&) = delete;
  Typesetter& operator=(const Typesetter&) = delete;

  // The first font's (DejaVu's), whatever the line holds, so that a Korean caption sits where an
  // English one does.
  LineMetrics metrics(Typeface face, int px);
  // The advance width of a line of text, in pixels.
  double width(std::string_view text, Typeface face, int px);
  // Draws one line with its baseline starting at `origin` (rounded to whole pixels).
  void draw(Mesh& mesh, std::string_view text, const TextStyle& style, const Vec2& origin);

  GlyphAtlas& atlas();
  // Characters drawn or measured so far that no font has (each drawn as a .notdef box).
  long missing_glyphs() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lamina::render
