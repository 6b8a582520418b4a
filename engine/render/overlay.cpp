#include "render/overlay.h"

#include <stdexcept>

namespace lamina::render {
namespace {

Overlay overlay_named(std::string_view name) {
  for (std::size_t i = 0; i < overlay_names.size(); ++i) {
    if (overlay_names[i] == name) return static_cast<Overlay>(i);
  }
  std::string known;
  for (std::string_view n : overlay_names) known += std::string(n) + ", ";
  throw std::invalid_argument("unknown overlay '" + std::string(name) + "' (known: " + known +
                              "all, none)");
}

}  // namespace

Overlays Overlays::parse(std::string_view list) {
  if (list == "all") return all();
  Overlays result;
  if (list == "none" || list.empty()) return result;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    result.set(overlay_named(list.substr(start, comma - start)));
    start = comma + 1;
  }
  return result;
}

std::string Overlays::to_string() const {
  std::string names;
  for (std::size_t i = 0; i < overlay_names.size(); ++i) {
    if (!bits_.test(i)) continue;
    if (!names.empty()) names += ',';
    names += overlay_names[i];
  }
  return names.empty() ? "none" : names;
}

}  // namespace lamina::render
