// Text with FreeType and the DejaVu faces: glyphs rasterised once into the atlas, then drawn as
// pixel-aligned textured rectangles (sharp at any MSAA setting).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "render/glyph_atlas.h"
#include "render/mesh.h"

namespace lamina::render {

enum class Typeface { sans, bold, mono };

// The DejaVu font file of a typeface (fonts-dejavu-core), for outputs that embed or name it.
std::string font_file(Typeface face);
// Its family name as SVG and CSS know it, e.g. "DejaVu Sans Mono", and whether it is bold.
std::string font_family(Typeface face);
bool is_bold(Typeface face);

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
  // Loads DejaVu Sans, Sans Bold and Sans Mono. Throws std::runtime_error naming the Debian
  // package when a font cannot be opened.
  Typesetter();
  ~Typesetter();
  Typesetter(const Typesetter&) = delete;
  Typesetter& operator=(const Typesetter&) = delete;

  LineMetrics metrics(Typeface face, int px);
  // The advance width of a line of text, in pixels.
  double width(std::string_view text, Typeface face, int px);
  // Draws one line with its baseline starting at `origin` (rounded to whole pixels).
  void draw(Mesh& mesh, std::string_view text, const TextStyle& style, const Vec2& origin);

  GlyphAtlas& atlas();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lamina::render
