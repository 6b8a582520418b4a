// The languages (language/language.h): English the key, Korean from ko.po as msgfmt compiled it
// into the library. That every message of the sources is in ko.po is the ctest
// catalogue_complete (tests/language/check_catalogue.cmake).
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "language/language.h"

using namespace lamina;

namespace {

// Sets a language for one test case and puts English back.
struct InLanguage {
  explicit InLanguage(Language language) { set_language(language); }
  ~InLanguage() { set_language(Language::en); }
};

}  // namespace

TEST_SUITE("language") {
  TEST_CASE("the codes: en and ko, nothing else") {
    CHECK(language_named("en") == Language::en);
    CHECK(language_named("ko") == Language::ko);
    CHECK_FALSE(language_named("xx").has_value());
    CHECK_FALSE(language_named("KO").has_value());
    CHECK(std::string(language_code(Language::ko)) == "ko");
    CHECK(language_codes() == "en, ko");
  }

  TEST_CASE("English is the key itself; Korean comes from the compiled ko.po") {
    const char* status = "t = {0} s · step {1} · Δt = {2} s";
    CHECK(current_language() == Language::en);
    CHECK(tr(status) == status);  // the same pointer: English is not looked up
    InLanguage korean(Language::ko);
    // ko.po's entry, as written there (an independent copy of the translation)
    CHECK(std::string(tr(status)) == "t = {0} s · 스텝 {1} · Δt = {2} s");
    // a message ko.po lacks stays English (catalogue_complete keeps the sources' all there)
    CHECK(std::string(tr("no such message")) == "no such message");
  }

  TEST_CASE("fill puts the values where the pattern says, in its own order") {
    CHECK(fill("t = {0} s · step {1}", {"0.500", "30"}) == "t = 0.500 s · step 30");
    CHECK(fill("{1}: {0}", {"a", "b"}) == "b: a");
    // what is no placeholder is kept: braces, a number past the values, a brace at the end
    CHECK(fill("{x} {2} {", {"a"}) == "{x} {2} {");
  }
  TEST_CASE("english_words: words of two or more Latin letters, but not units, functions or names") {
    using Words = std::vector<std::string>;
    // words left, in order, each once per occurrence
    CHECK(english_words("friction λu") == Words{"friction"});
    CHECK(english_words("Ch 1 · Fig 1-2 (eq. 1-27)") == Words{"Ch", "Fig", "eq"});
    // Korean, symbols, numbers with exponents, units and the equations' functions are kept
    CHECK(english_words("마찰력 λu = 0.25 N, |ṙᵢ| = |sin α| |rᵢ| |ω| = 1.2e-4 m/s, 0.8 rad/s").empty());
    CHECK(english_words("max|Ṙ Rᵀ − Skew(ω)| = 3e-10 (식 1-27)").empty());
    // names the Korean keeps: solvers and pitfalls as --solver and --pitfall take them
    CHECK(english_words("솔버: soft-step · 함정: no-warm-start · Box2D v3.1.1 · PGS").empty());
    // a hyphen or a digit joins a word, so a name's part is no pass for an English word
    CHECK(english_words("soft-steps") == Words{"soft-steps"});
    CHECK(english_words("pgs2") == Words{"pgs2"});
    // one letter is a symbol, not a word; so is a letter after a digit (1e-4, 2D)
    CHECK(english_words("x, v, J, q = w + (x, y, z), 3D").empty());
    // a subscript after "_" is part of its symbol (eq. 5-2's F_ext)
    CHECK(english_words("F_ext = [m1 g, 0, 0, 0], λ_exp").empty());
  }
}
