// The axes overlay: a light metre grid behind the scene; axis lines, ticks and their labels on
// top of it, so the ground's band never hides a label.
#include <cmath>
#include <cstdio>

#include "render/paint.h"

namespace lamina::render {
namespace {

// The 1, 2 or 5 × 10^k at or above `raw`: tick spacings a reader can add up in their head.
double nice_step(double raw) {
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / decade;
  return (f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0) * decade;
}

// The ticks of one axis: k·step for k in [first, last], in metres.
struct Ticks {
  double step;
  long first;
  long last;

  std::string text(long k) const {
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    char number[32];
    std::snprintf(number, sizeof number, "%.*f", decimals, static_cast<double>(k) * step);
    return std::string(number) + (k == last ? " m" : "");
  }
};

// Ticks every ~90 pixels over the world range [low, high].
Ticks ticks(const Canvas& c, double low, double high) {
  const double step = nice_step(90.0 * c.style.unit / c.camera.pixels_per_metre());
  return {step, static_cast<long>(std::ceil(low / step - 1e-9)),
          static_cast<long>(std::floor(high / step + 1e-9))};
}

Rect axes_area(const Canvas& c) { return c.style.drawing_area(c.size, true); }

// x ticks (vertical lines, labels below) and y ticks (horizontal lines, labels to the left).
Ticks x_ticks(const Canvas& c) {
  const Rect a = axes_area(c);
  return ticks(c, c.camera.to_world(a.min).x(), c.camera.to_world(a.max).x());
}
Ticks y_ticks(const Canvas& c) {
  const Rect a = axes_area(c);
  return ticks(c, c.camera.to_world(a.max).y(), c.camera.to_world(a.min).y());
}

}  // namespace

void paint_grid(const Frame&, Canvas& c) {
  if (!c.overlays.has(Overlay::axes)) return;
  const Rect a = axes_area(c);
  const Ticks tx = x_ticks(c), ty = y_ticks(c);
  for (long k = tx.first; k <= tx.last; ++k) {
    const double x = c.px(Vec2(k * tx.step, 0.0)).x();
    c.draw.stroke_segment(Vec2(x, a.min.y()), Vec2(x, a.max.y()), c.style.unit, palette::grid);
  }
  for (long k = ty.first; k <= ty.last; ++k) {
    const double y = c.px(Vec2(0.0, k * ty.step)).y();
    c.draw.stroke_segment(Vec2(a.min.x(), y), Vec2(a.max.x(), y), c.style.unit, palette::grid);
  }
}

void paint_axes(const Frame&, Canvas& c) {
  if (!c.overlays.has(Overlay::axes)) return;
  const Rect a = axes_area(c);
  const double tick = 6.0 * c.style.unit;
  const TextStyle style{Typeface::sans, c.style.tick_px, palette::grey};
  const Ticks tx = x_ticks(c), ty = y_ticks(c);
  for (long k = tx.first; k <= tx.last; ++k) {
    const double x = c.px(Vec2(k * tx.step, 0.0)).x();
    c.draw.stroke_segment(Vec2(x, a.max.y()), Vec2(x, a.max.y() + tick), c.style.unit,
                   palette::grey);
    c.write(tx.text(k), style, Vec2(x, a.max.y() + tick + 0.7 * c.style.tick_px), 0.5);
  }
  for (long k = ty.first; k <= ty.last; ++k) {
    const double y = c.px(Vec2(0.0, k * ty.step)).y();
    c.draw.stroke_segment(Vec2(a.min.x() - tick, y), Vec2(a.min.x(), y), c.style.unit,
                   palette::grey);
    c.write(ty.text(k), style, Vec2(a.min.x() - 1.5 * tick, y), 1.0);
  }
  c.draw.stroke_segment(Vec2(a.min.x(), a.max.y()), a.max, c.style.unit, palette::grey);
  c.draw.stroke_segment(a.min, Vec2(a.min.x(), a.max.y()), c.style.unit, palette::grey);
}

}  // namespace lamina::render
