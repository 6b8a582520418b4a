#include "render/font_set.h"

#include <ft2build.h>

#include <stdexcept>
#include FT_FREETYPE_H

#include "render/utf8.h"

namespace lamina::render {
namespace {

std::string dejavu(const char* file) { return std::string(LAMINA_FONT_DIR) + "/" + file; }
std::string nanum(const char* file) { return std::string(LAMINA_HANGUL_FONT_DIR) + "/" + file; }

// The chains, in Typeface order. Nanum's own Latin and Greek are never reached: DejaVu has them.
const std::array<std::vector<FontFile>, 3>& chains() {
  static const std::array<std::vector<FontFile>, 3> table = {{
      {{dejavu("DejaVuSans.ttf"), "DejaVu Sans"}, {nanum("NanumGothic.ttf"), "NanumGothic"}},
      {{dejavu("DejaVuSans-Bold.ttf"), "DejaVu Sans"},
       {nanum("NanumGothicBold.ttf"), "NanumGothic"}},
      {{dejavu("DejaVuSansMono.ttf"), "DejaVu Sans Mono"},
       {nanum("NanumGothicCoding.ttf"), "NanumGothicCoding"}},
  }};
  return table;
}

// UTF-8 of one code point (decode_utf8's inverse), to cut lines into runs.
void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

}  // namespace

const std::vector<FontFile>& font_chain(Typeface face) {
  return chains()[static_cast<std::size_t>(face)];
}

std::string font_family(Typeface face) {
  std::string list;
  for (const FontFile& font : font_chain(face)) list += (list.empty() ? "" : ", ") + font.family;
  return list;
}

bool is_bold(Typeface face) { return face == Typeface::bold; }

FontSet::FontSet() {
  if (FT_Init_FreeType(&library_) != 0) throw std::runtime_error("cannot start FreeType");
  for (std::size_t t = 0; t < faces_.size(); ++t) {
    for (const FontFile& font : chains()[t]) {
      FT_Face f = nullptr;
      if (FT_New_Face(library_, font.path.c_str(), 0, &f) != 0) {
        const bool hangul = font.path.find("nanum") != std::string::npos;
        const std::string package = hangul ? "fonts-nanum" : "fonts-dejavu-core";
        close();  // the faces opened so far
        throw std::runtime_error("cannot open the font " + font.path + " (install the Debian package " +
                                 package + ")");
      }
      faces_[t].push_back(f);
    }
  }
}

FontSet::~FontSet() { close(); }

void FontSet::close() {
  for (std::vector<FT_FaceRec_*>& chain : faces_) {
    for (FT_Face f : chain) FT_Done_Face(f);
    chain.clear();
  }
  if (library_ != nullptr) FT_Done_FreeType(library_);
  library_ = nullptr;
}

FT_Face FontSet::face(Typeface face, std::size_t font) const {
  return faces_[static_cast<std::size_t>(face)][font];
}

std::size_t FontSet::font_for(Typeface face, char32_t point) {
  const std::vector<FT_FaceRec_*>& chain = faces_[static_cast<std::size_t>(face)];
  for (std::size_t k = 0; k < chain.size(); ++k) {
    if (FT_Get_Char_Index(chain[k], point) != 0) return k;
  }
  ++missing_;
  return 0;
}

std::vector<TextRun> FontSet::runs(std::string_view text, Typeface face) {
  std::vector<TextRun> out;
  for (const char32_t point : decode_utf8(text)) {
    const std::size_t font = font_for(face, point);
    if (out.empty() || out.back().font != font) out.push_back({font, {}});
    append_utf8(out.back().text, point);
  }
  return out;
}

}  // namespace lamina::render
