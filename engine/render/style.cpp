#include "render/style.h"

#include <algorithm>
#include <cmath>

namespace lamina::render {
namespace {

constexpr double reference_height = 720.0;

int font_px(double reference_px, double unit) {
  return std::max(8, static_cast<int>(std::lround(reference_px * unit)));
}

}  // namespace

Style Style::for_size(const FrameSize& size) {
  const double u = size.height / reference_height;
  Style s;
  s.unit = u;
  s.outline = 2.0 * u;
  s.line = 2.0 * u;
  s.arrow = 2.5 * u;
  s.marker = 6.0 * u;
  s.margin = 16.0 * u;
  s.caption_px = font_px(24, u);
  s.text_px = font_px(19, u);
  s.mono_px = font_px(17, u);
  s.tick_px = font_px(15, u);
  return s;
}

double Style::top_bar() const { return 1.3 * caption_px + 2.0 * margin; }

Rect Style::drawing_area(const FrameSize& size, bool axes) const {
  const double left = axes ? margin + 3.5 * tick_px : margin;
  const double bottom = axes ? margin + 1.6 * tick_px : margin;
  return {Vec2(left, top_bar()), Vec2(size.width - margin, size.height - bottom)};
}

}  // namespace lamina::render
