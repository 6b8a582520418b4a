// The language of everything Lamina writes for people to read: frames, plots, the viewer and
// explanations. English is the key of every message, as gettext's msgid is, written once where
// it is used (tr("...")); Korean, the language of the text Lamina follows, comes from
// engine/language/ko.po, the form translators and their tools know, compiled by Debian's msgfmt
// at build time into the program (docs/slides.md, "Languages").
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

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

// `english` in the current language: itself in English, its Korean from ko.po in Korean (or
// itself when ko.po lacks it; the test catalogue_complete keeps every message of the sources in
// ko.po).
const char* tr(const char* english);

// A message with its values: "{0}", "{1}", … in `pattern` replaced by values[0], values[1], …,
// so that a translation may put them in its own order.
std::string fill(std::string_view pattern, std::initializer_list<std::string_view> values);

}  // namespace lamina
