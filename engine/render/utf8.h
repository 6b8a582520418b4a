// UTF-8 text to Unicode code points (labels carry ω, θ, λ, Δ, ², ᵀ, ...).
#pragma once

#include <string_view>
#include <vector>

namespace lamina::render {

// The code points of a UTF-8 string; a malformed sequence becomes U+FFFD.
std::vector<char32_t> decode_utf8(std::string_view text);

}  // namespace lamina::render
