// The fonts every output draws text with, opened by FreeType: for each typeface a chain, first
// to last, and a character is drawn by the first font of the chain that has it. DejaVu comes
// first (Latin, Greek and the mathematical symbols: λ, ω, Δ, ², ᵀ), then Nanum Gothic for Hangul
// (Korean captions follow the text Lamina reads, which is written in Korean). Both from Debian:
// fonts-dejavu-core and fonts-nanum. The PNG frames (typesetter.h), the SVG's font-family list and
// the PDF's embedded fonts (vector_output.h) all take the same chain from here.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

// FreeType's handles (FT_Face, FT_Library), declared so that users of the set need not see
// FreeType's headers.
struct FT_FaceRec_;
struct FT_LibraryRec_;

namespace lamina::render {

enum class Typeface { sans, bold, mono };

// One font of a chain: its file and its family name as SVG and CSS know it.
struct FontFile {
  std::string path;
  std::string family;
};

// A typeface's chain, first to last.
const std::vector<FontFile>& font_chain(Typeface face);
// The chain's families as an SVG font-family list: "DejaVu Sans, NanumGothic".
std::string font_family(Typeface face);
bool is_bold(Typeface face);

// A piece of a line drawn by one font of its chain.
struct TextRun {
  std::size_t font;  // index into the chain
  std::string text;  // UTF-8
};

// Every font of every chain, open. Not copyable: it owns its FreeType library and faces.
class FontSet {
 public:
  // Throws std::runtime_error naming the Debian package when a font cannot be opened.
  FontSet();
  ~FontSet();
  FontSet(const FontSet&) = delete;
  FontSet& operator=(const FontSet&) = delete;

  FT_FaceRec_* face(Typeface face, std::size_t font) const;  // an FT_Face
  // The first font of the chain that has the character; a character none has is counted as a
  // missing glyph and drawn by the first font (its .notdef box).
  std::size_t font_for(Typeface face, char32_t point);
  // A line cut into runs of one font each.
  std::vector<TextRun> runs(std::string_view text, Typeface face);
  // Characters asked for that no font of their chain has, since the set was opened.
  long missing_glyphs() const { return missing_; }

 private:
  void close();  // every face and the library

  FT_LibraryRec_* library_ = nullptr;
  std::array<std::vector<FT_FaceRec_*>, 3> faces_;
  long missing_ = 0;
};

}  // namespace lamina::render
