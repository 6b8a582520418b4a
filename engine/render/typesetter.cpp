#include "render/typesetter.h"

#include <ft2build.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include FT_FREETYPE_H

#include "render/utf8.h"

namespace lamina::render {
namespace {

// FreeType's 26.6 fixed point to pixels.
double from_26_6(long value) { return value / 64.0; }

// One rasterised glyph: where it is in the atlas and how it sits on the baseline.
struct Glyph {
  Rect uv;        // its spot in the atlas
  int left = 0;   // pen position to the bitmap's left edge, in pixels
  int top = 0;    // baseline to the bitmap's top edge, in pixels (up is positive)
  int width = 0;  // bitmap size, in pixels
  int height = 0;
  long advance = 0;  // pen advance, in 1/64 pixel
};

}  // namespace

struct Typesetter::Impl {
  FontSet fonts;
  std::map<std::tuple<Typeface, int, char32_t>, Glyph> glyphs;
  GlyphAtlas atlas;

  FT_Face sized(Typeface face, std::size_t font, int px) {
    FT_Face f = fonts.face(face, font);
    FT_Set_Pixel_Sizes(f, 0, static_cast<FT_UInt>(px));
    return f;
  }

  const Glyph& glyph(Typeface face, int px, char32_t point) {
    const auto key = std::make_tuple(face, px, point);
    const auto found = glyphs.find(key);
    if (found != glyphs.end()) return found->second;
    FT_Face f = sized(face, fonts.font_for(face, point), px);
    if (FT_Load_Char(f, point, FT_LOAD_RENDER) != 0) {
      throw std::runtime_error("FreeType cannot render U+" + std::to_string(point));
    }
    const FT_Bitmap& bitmap = f->glyph->bitmap;
    Glyph g;
    g.width = static_cast<int>(bitmap.width);
    g.height = static_cast<int>(bitmap.rows);
    g.left = f->glyph->bitmap_left;
    g.top = f->glyph->bitmap_top;
    g.advance = f->glyph->advance.x;
    if (g.width > 0 && g.height > 0)
      g.uv = atlas.add(g.width, g.height, bitmap.buffer, bitmap.pitch);
    return glyphs.emplace(key, g).first->second;
  }
};

Typesetter::Typesetter() : impl_(std::make_unique<Impl>()) {}

Typesetter::~Typesetter() = default;

LineMetrics Typesetter::metrics(Typeface face, int px) {
  const FT_Size_Metrics& m = impl_->sized(face, 0, px)->size->metrics;
  return {from_26_6(m.ascender), -from_26_6(m.descender), from_26_6(m.height)};
}

double Typesetter::width(std::string_view text, Typeface face, int px) {
  long pen = 0;
  for (char32_t point : decode_utf8(text)) pen += impl_->glyph(face, px, point).advance;
  return from_26_6(pen);
}

void Typesetter::draw(Mesh& mesh, std::string_view text, const TextStyle& style,
                      const Vec2& origin) {
  const double x0 = std::round(origin.x()), baseline = std::round(origin.y());
  long pen = 0;
  for (char32_t point : decode_utf8(text)) {
    const Glyph& g = impl_->glyph(style.face, style.px, point);
    if (g.width > 0 && g.height > 0) {
      const Vec2 corner(x0 + std::round(from_26_6(pen)) + g.left, baseline - g.top);
      mesh.glyph({corner, corner + Vec2(g.width, g.height)}, g.uv, style.colour);
    }
    pen += g.advance;
  }
}

GlyphAtlas& Typesetter::atlas() { return impl_->atlas; }

long Typesetter::missing_glyphs() const { return impl_->fonts.missing_glyphs(); }

}  // namespace lamina::render
