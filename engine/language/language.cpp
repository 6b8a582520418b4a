#include "language/language.h"

#include <cstdint>
#include <cctype>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

namespace lamina {

// engine/language/ko/*.po as msgcat joined and msgfmt compiled them (catalogue_ko.cpp, written at build time by embed_catalogue.cmake).
extern const unsigned char ko_catalogue[];
extern const std::size_t ko_catalogue_size;

namespace {

Language current = Language::en;

// A GNU .mo file's messages, msgid to msgstr (the format of gettext's manual, "The Format of GNU
// MO Files"): a header of 32-bit words (magic 0x950412de in the file's byte order, revision, N,
// the offsets of the originals' and the translations' tables), each table N pairs (length,
// offset) of NUL-terminated strings. The header entry, msgid "", is left out.
std::map<std::string, std::string> read_mo(const unsigned char* bytes, std::size_t size) {
  auto word = [&](std::size_t at) {
    if (at + 4 > size) throw std::logic_error("the compiled catalogue is cut short");
    std::uint32_t w;
    std::memcpy(&w, bytes + at, 4);  // msgfmt writes the build machine's order, which reads it
    return static_cast<std::size_t>(w);
  };
  if (word(0) != 0x950412de) throw std::logic_error("the compiled catalogue is not a .mo file");
  const std::size_t count = word(8), originals = word(12), translations = word(16);
  auto text = [&](std::size_t table, std::size_t i) {
    const std::size_t length = word(table + 8 * i), offset = word(table + 8 * i + 4);
    if (offset + length > size) throw std::logic_error("the compiled catalogue is cut short");
    return std::string(reinterpret_cast<const char*>(bytes) + offset, length);
  };
  std::map<std::string, std::string> messages;
  for (std::size_t i = 0; i < count; ++i) {
    std::string id = text(originals, i);
    if (!id.empty()) messages.emplace(std::move(id), text(translations, i));
  }
  return messages;
}

const std::map<std::string, std::string>& korean() {
  static const std::map<std::string, std::string> messages = read_mo(ko_catalogue, ko_catalogue_size);
  return messages;
}

}  // namespace

const char* language_code(Language language) { return language == Language::ko ? "ko" : "en"; }

std::optional<Language> language_named(std::string_view code) {
  if (code == "en") return Language::en;
  if (code == "ko") return Language::ko;
  return std::nullopt;
}

std::string language_codes() { return "en, ko"; }

void set_language(Language language) { current = language; }

Language current_language() { return current; }

const char* tr(const char* english) {
  if (current == Language::en) return english;
  const auto found = korean().find(english);
  return found == korean().end() ? english : found->second.c_str();
}

std::vector<std::pair<std::string, std::string>> translations() {
  if (current == Language::en) return {};
  return {korean().begin(), korean().end()};
}

std::string fill(std::string_view pattern, std::initializer_list<std::string_view> values) {
  const std::vector<std::string_view> list(values);
  std::string out;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] == '{' && i + 2 < pattern.size() && pattern[i + 2] == '}' &&
        pattern[i + 1] >= '0' && pattern[i + 1] <= '9' &&
        static_cast<std::size_t>(pattern[i + 1] - '0') < list.size()) {
      out += list[static_cast<std::size_t>(pattern[i + 1] - '0')];
      i += 2;
    } else {
      out += pattern[i];
    }
  }
  return out;
}

std::vector<std::string> english_words(std::string_view text) {
  // What a Korean frame keeps in Latin letters. Units (SI, as the text writes them), the
  // functions of its equations, and names: methods and algorithms by their authors' names or
  // acronyms, the libraries and formats Lamina names, its solvers and pitfalls by their names
  // (what `--solver` and `--pitfall` take).
  static const std::set<std::string_view> kept = {
      "Box2D", "CSV", "EPA", "GJK", "Gauss-Seidel", "Hz", "JSON", "LCP", "Lamina", "Lemke",
      "MLCP", "PGS", "PNG", "Rodrigues", "Rz", "Skew", "XPBD", "abs", "atan2", "baumgarte-no-slop", "block",
      "clamp-increment", "cm", "cos", "crude-friction", "det", "diag", "exact", "exp", "fps",
      "islands", "kg", "lambda-b1", "ln", "log", "max", "min", "mm", "ms", "no-renormalisation",
      "no-warm-start", "pgs", "px", "rad", "sgn", "sign", "sin", "soft-step", "sqrt", "tan",
      "text", "v3", "v3.1.1"};
  std::vector<std::string> words;
  const auto latin = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  std::size_t i = 0;
  while (i < text.size()) {
    // a word starts a run of letters; one after a letter, a digit or "_" is a symbol's part
    // (Box2D's "D", 1e-4's "e", F_ext's "ext")
    if (!latin(text[i]) ||
        (i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) != 0 || text[i - 1] == '_'))) {
      ++i;
      continue;
    }
    std::size_t end = i, letters = 0;
    while (end < text.size()) {
      const char c = text[end];
      if (latin(c)) {
        ++letters;
      } else if (!(std::isdigit(static_cast<unsigned char>(c)) != 0 ||
                   ((c == '-' || c == '.') && end + 1 < text.size() &&
                    std::isalnum(static_cast<unsigned char>(text[end + 1])) != 0))) {
        break;
      }
      ++end;
    }
    const std::string_view word = text.substr(i, end - i);
    if (letters >= 2 && kept.count(word) == 0) words.emplace_back(word);
    i = end;
  }
  return words;
}

}  // namespace lamina
