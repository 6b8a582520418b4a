// The language of everything Lamina writes for people to read: frames, plots, the viewer and
// explanations. English is the key of every message, as gettext's msgid is, written once where
// it is used (tr("...")); Korean, the language of the text Lamina follows, comes from
// engine/language/ko/*.po, the form translators and their tools know, joined and compiled by msgfmt
// at build time into the program (docs/slides.md, "Languages").
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lamina {

enum class Language { en, ko };

// "en" or "ko", and back; std::nullopt for a name that is no language Lamina has.
const char* language_code(Language language);
std::optional<Language> language_named(std::string_view code);
// Every language by code, for messages: "en, ko".
std::string language_codes();

// The process's language (English unless set), like the C library's locale: set once, when the
// options are read, before anything is written.
void set_language(Language language);
Language current_language();

// `english` in the current language: itself in English, its Korean from the catalogue in Korean (or
// itself when it lacks it; the test catalogue_complete keeps every message of the sources in
// engine/language/ko/).
const char* tr(const char* english);

// Every message of the current language's catalogue, English then translated, in the English's
// order; none in English. For what carries its own words, as the viewer's page does.
std::vector<std::pair<std::string, std::string>> translations();

// Marks `english` as a message of the catalogue where it is written but not shown yet (a table
// made before the language is set); tr() translates it where it is shown. xgettext reads msg("…")
// as it reads tr("…").
constexpr const char* msg(const char* english) { return english; }

// Which words a message takes: tr (the current language's) or as_written (the English, for what
// is kept rather than shown: a scene file, a trace).
using Wording = const char* (*)(const char*);
inline const char* as_written(const char* english) { return english; }

// A message with its values: "{0}", "{1}", … in `pattern` replaced by values[0], values[1], …,
// so that a translation may put them in its own order.
std::string fill(std::string_view pattern, std::initializer_list<std::string_view> values);

// The English words left in `text`, a line drawn in Korean (the check of `--check-layout --lang
// ko`): runs of two or more Latin letters, with the hyphens and digits that join them
// ("soft-step", "Box2D"), that are neither a unit (m/s, rad, kg), a function of the equations
// (sin, max, Skew), nor a name the Korean keeps as it is (PGS, MLCP, Lemke, Box2D, Lamina, the
// solvers' names). One letter is a symbol (x, v, J), never a word, and so is a subscript
// (F_ext, λ_exp).
std::vector<std::string> english_words(std::string_view text);

}  // namespace lamina
