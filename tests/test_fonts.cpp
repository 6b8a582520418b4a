// The fonts text is drawn with (render/font_set.h): a chain per typeface, DejaVu then Nanum
// Gothic, so that one caption may hold Hangul, Latin, Greek and mathematical symbols, each drawn
// by the first font that has it, and a character no font has is counted, not drawn silently as
// a box.
#include <doctest/doctest.h>

#include <string>

#include "render/font_set.h"
#include "render/typesetter.h"
#include "render/utf8.h"

using namespace lamina::render;

namespace {

// A caption as a Korean frame writes it: the text's own terms (구속조건 constraint, 충돌
// collision, 관성텐서 inertia tensor), its equation form (식 3-16), symbols and numbers.
const std::string korean = "식 3-16: 구속조건 λ = 40.000 N, 충돌 ω̇ Δt², 관성텐서 Jᵀ";

// The characters of a line that draw something (not spaces).
int inked(const std::string& line) {
  int n = 0;
  for (const char32_t c : decode_utf8(line)) n += c != U' ';
  return n;
}

}  // namespace

TEST_SUITE("fonts") {
  TEST_CASE("every typeface's chain draws a Korean caption with no missing glyph") {
    Typesetter text;
    for (const Typeface face : {Typeface::sans, Typeface::bold, Typeface::mono}) {
      CAPTURE(static_cast<int>(face));
      Mesh mesh(text.atlas().solid_uv());
      text.draw(mesh, korean, {face, 19, palette::ink}, {10.0, 40.0});
      // every character but the spaces is a glyph of two triangles: none came out empty
      // (combining dot over ω included: it has ink)
      CHECK(mesh.vertices().size() == 6u * static_cast<unsigned>(inked(korean)));
      CHECK(text.missing_glyphs() == 0);
      // a Hangul syllable is full width, one em (19 px, within the 1 px of hinting), where
      // DejaVu's .notdef box would be about 0.6 em
      CHECK(text.width("구", face, 19) == doctest::Approx(19.0).epsilon(1.0 / 19.0));
    }
  }

  TEST_CASE("a character comes from the first font of the chain that has it") {
    FontSet fonts;
    CHECK(fonts.font_for(Typeface::sans, U'A') == 0);     // DejaVu Sans
    CHECK(fonts.font_for(Typeface::sans, U'λ') == 0);     // DejaVu's Greek, not Nanum's
    CHECK(fonts.font_for(Typeface::sans, U'구') == 1);    // Nanum Gothic
    CHECK(fonts.font_for(Typeface::mono, U'식') == 1);    // Nanum Gothic Coding
    CHECK(fonts.missing_glyphs() == 0);
    const std::vector<TextRun> runs = fonts.runs("λ = 3 구속조건 N", Typeface::bold);
    REQUIRE(runs.size() == 3);
    CHECK(runs[0].text == "λ = 3 ");
    CHECK(runs[1].text == "구속조건");
    CHECK(runs[2].text == " N");
    CHECK(runs[1].font == 1);
    CHECK(font_family(Typeface::sans) == "DejaVu Sans, NanumGothic");
  }

  TEST_CASE("a character no font has is counted as missing") {
    Typesetter text;
    // U+A000, a Yi syllable: neither DejaVu nor Nanum has Yi
    Mesh mesh(text.atlas().solid_uv());
    text.draw(mesh, "ꀀ", {Typeface::sans, 19, palette::ink}, {10.0, 40.0});
    CHECK(text.missing_glyphs() == 1);
    // measured again: the glyph is cached, the count stays one lookup per character and size
    CHECK(text.width("ꀀ", Typeface::sans, 19) > 0.0);
    CHECK(text.missing_glyphs() == 1);
  }

  TEST_CASE("an English line is one run of DejaVu: its frames are drawn as before the chain") {
    FontSet fonts;
    const std::vector<TextRun> runs = fonts.runs("Fig 4-3  λ = 40.000 N, ω̇ Δt², Jᵀ", Typeface::sans);
    REQUIRE(runs.size() == 1);
    CHECK(runs[0].font == 0);
  }
}
