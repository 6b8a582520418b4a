#include "scene/json_layout.h"

namespace lamina {
namespace {

using Json = nlohmann::ordered_json;

std::string key_prefix(const std::string& key) { return key.empty() ? "" : Json(key).dump() + ": "; }

// The value on one line, with a space after each ',' and ':'.
std::string one_line(const Json& value) {
  if (!value.is_structured()) return value.dump();
  std::string text;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!text.empty()) text += ", ";
    text += (value.is_object() ? key_prefix(it.key()) : "") + one_line(it.value());
  }
  return value.is_object() ? "{" + text + "}" : "[" + text + "]";
}

// `key: value` (no key inside arrays) at `indent` spaces, on one line when it fits.
std::string laid_out(const std::string& key, const Json& value, std::size_t indent, std::size_t width) {
  const std::string margin(indent, ' ');
  const std::string flat = margin + key_prefix(key) + one_line(value);
  if (!value.is_structured() || value.empty() || flat.size() <= width) return flat;
  std::string text = margin + key_prefix(key) + (value.is_object() ? "{" : "[");
  for (auto it = value.begin(); it != value.end(); ++it) {
    text += (it == value.begin() ? "\n" : ",\n") +
            laid_out(value.is_object() ? it.key() : "", it.value(), indent + 2, width);
  }
  return text + "\n" + margin + (value.is_object() ? "}" : "]");
}

}  // namespace

std::string layout_json(const Json& value, std::size_t width) { return laid_out("", value, 0, width); }

}  // namespace lamina
