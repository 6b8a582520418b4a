#include "render/typesetter.h"

#include <ft2build.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include FT_FREETYPE_H

#include "render/utf8.h"

namespace lamina::render {
namespace {

constexpr std::array<const char*, 3> face_files{"DejaVuSans.ttf", "DejaVuSans-Bold.ttf",
                                                "DejaVuSansMono.ttf"};

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
  FT_Library library = nullptr;
  std::array<FT_Face, face_files.size()> faces{};
  std::map<std::tuple<Typeface, int, char32_t>, Glyph> glyphs;
  GlyphAtlas atlas;

  FT_Face sized(Typeface face, int px) {
    FT_Face f = faces[static_cast<std::size_t>(face)];
    FT_Set_Pixel_Sizes(f, 0, static_cast<FT_UInt>(px));
    return f;
  }

  const Glyph& glyph(Typeface face, int px, char32_t point) {
    const auto key = std::make_tuple(face, px, point);
    const auto found = glyphs.find(key);
    if (found != glyphs.end()) return found->second;
    FT_Face f = sized(face, px);
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

std::string font_file(Typeface face) {
  return std::string(LAMINA_FONT_DIR) + "/" + face_files[static_cast<std::size_t>(face)];
}

std::string font_family(Typeface face) { return face == Typeface::mono ? "DejaVu Sans Mono" : "DejaVu Sans"; }

bool is_bold(Typeface face) { return face == Typeface::bold; }

Typesetter::Typesetter() : impl_(std::make_unique<Impl>()) {
  if (FT_Init_FreeType(&impl_->library) != 0) throw std::runtime_error("cannot start FreeType");
  for (std::size_t i = 0; i < face_files.size(); ++i) {
    const std::string path = font_file(static_cast<Typeface>(i));
    if (FT_New_Face(impl_->library, path.c_str(), 0, &impl_->faces[i]) != 0) {
      FT_Done_FreeType(impl_->library);
      throw std::runtime_error("cannot open font " + path +
                               " (install the Debian package fonts-dejavu-core)");
    }
  }
}

Typesetter::~Typesetter() {
  for (FT_Face face : impl_->faces) FT_Done_Face(face);
  FT_Done_FreeType(impl_->library);
}

LineMetrics Typesetter::metrics(Typeface face, int px) {
  const FT_Size_Metrics& m = impl_->sized(face, px)->size->metrics;
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

}  // namespace lamina::render
