// Caption, status line and the corner panels of numbers.
#include <algorithm>
#include <string>

#include "render/paint.h"

namespace lamina::render {
namespace {

// Height of one line of the face at its size, in pixels.
double line_height(Canvas& c, Typeface face, int px) { return c.text.metrics(face, px).height; }

// The longest start of `line` (whole UTF-8 characters) that fits `room` pixels with "…" after
// it, and the "…"; the line itself when it fits.
std::string fitted(Canvas& c, const std::string& line, const TextStyle& style, double room) {
  if (c.text.width(line, style.face, style.px) <= room) return line;
  std::size_t keep = line.size();
  while (keep > 0) {
    do {
      --keep;  // back to the first byte of a character
    } while (keep > 0 && (static_cast<unsigned char>(line[keep]) & 0xC0) == 0x80);
    const std::string shorter = line.substr(0, keep) + "…";
    if (c.text.width(shorter, style.face, style.px) <= room) return shorter;
  }
  return "…";
}

// The caption at the top left, shrunk when it would run into the status line at the top right,
// down to 8 px, and cut short with "…" only when even that is too long (a 320 × 180 frame). The
// status gets at least 30 % of the width, so a growing step count does not change the caption's
// size from one frame of a sequence to the next. Both lines are labels of the layout: the layout
// check finds them over each other.
void paint_top_bar(const Frame& frame, Canvas& c) {
  const double middle = c.style.margin + 0.65 * c.style.caption_px;
  const double status =
      std::max(c.text.width(frame.status, Typeface::sans, c.style.text_px), 0.3 * c.size.width);
  const double room = c.size.width - 4.0 * c.style.margin - status;
  const double natural = c.text.width(frame.caption, Typeface::bold, c.style.caption_px);
  int px = natural <= room ? c.style.caption_px
                           : std::max(8, static_cast<int>(c.style.caption_px * room / natural));
  // a face's width is not quite proportional to its size (hinting, rounding): a pixel smaller
  // while it still does not fit, so that a caption is cut short only below 8 px
  while (px > 8 && c.text.width(frame.caption, Typeface::bold, px) > room) --px;
  const TextStyle caption{Typeface::bold, px, palette::ink};
  const Rect caption_box =
      c.write(fitted(c, frame.caption, caption, room), caption, Vec2(c.style.margin, middle));
  const Rect status_box = c.write(frame.status, {Typeface::sans, c.style.text_px, palette::grey},
                                  Vec2(c.size.width - c.style.margin, middle), 1.0);
  if (!frame.caption.empty()) c.mark(LayoutBox::Kind::label, caption_box);
  if (!frame.status.empty()) c.mark(LayoutBox::Kind::label, status_box);
  const double rule = c.style.top_bar() - 0.5 * c.style.margin;
  c.draw.stroke_segment(Vec2(c.style.margin, rule), Vec2(c.size.width - c.style.margin, rule),
                 c.style.unit, palette::grid);
}

Vec2 panel_size(Canvas& c, const Panel& panel) {
  double width = c.text.width(panel.title, Typeface::bold, c.style.text_px);
  for (const std::string& line : panel.lines) {
    width = std::max(width, c.text.width(line, Typeface::mono, c.style.mono_px));
  }
  const double title = panel.title.empty() ? 0.0 : line_height(c, Typeface::bold, c.style.text_px);
  const double rows = panel.lines.size() * line_height(c, Typeface::mono, c.style.mono_px);
  return Vec2(width, title + rows) + Vec2::Constant(2.0 * panel_padding(c.style));
}

void paint_panel(Canvas& c, const Panel& panel) {
  const Vec2 size = panel_size(c, panel);
  const Vec2 corner = corner_position(c, panel.corner, size);
  draw_text_box(c, {corner, corner + size});
  c.mark(LayoutBox::Kind::panel, {corner, corner + size});
  const double pad = panel_padding(c.style);
  double y = corner.y() + pad;
  if (!panel.title.empty()) {
    const double h = line_height(c, Typeface::bold, c.style.text_px);
    c.write(panel.title, {Typeface::bold, c.style.text_px, panel.title_colour},
            Vec2(corner.x() + pad, y + 0.5 * h));
    y += h;
  }
  const double h = line_height(c, Typeface::mono, c.style.mono_px);
  for (const std::string& line : panel.lines) {
    c.write(line, {Typeface::mono, c.style.mono_px, palette::ink},
            Vec2(corner.x() + pad, y + 0.5 * h));
    y += h;
  }
}

}  // namespace

Rect Canvas::write(std::string_view line, const TextStyle& style, const Vec2& anchor,
                   double align_x) const {
  const LineMetrics m = text.metrics(style.face, style.px);
  const double width = text.width(line, style.face, style.px);
  const double left = anchor.x() - align_x * width;
  const double baseline = anchor.y() + 0.5 * (m.ascender - m.descender);
  draw.text(line, style, Vec2(left, baseline));
  return {Vec2(left, baseline - m.ascender), Vec2(left + width, baseline + m.descender)};
}

void Canvas::write_label(std::string_view line, const TextStyle& style, const Vec2& anchor,
                         double align_x) const {
  if (line.empty()) return;
  // A label goes where it is asked unless a label drawn before covers that place; then a line
  // lower, or higher, or two lower: labels never cover each other.
  const LineMetrics m = text.metrics(style.face, style.px);
  const double width = text.width(line, style.face, style.px), height = m.ascender + m.descender;
  const auto box_at = [&](const Vec2& at) {
    const double left = at.x() - align_x * width, top = at.y() + 0.5 * (m.ascender - m.descender) - m.ascender;
    return Rect{Vec2(left, top), Vec2(left + width, top + height)};
  };
  const auto free = [&](const Rect& box) {
    for (const LayoutBox& b : draw.layout()) {
      if (b.kind != LayoutBox::Kind::label) continue;
      if (box.min.x() < b.rect.max.x() && b.rect.min.x() < box.max.x() && box.min.y() < b.rect.max.y() &&
          b.rect.min.y() < box.max.y()) {
        return false;
      }
    }
    return true;
  };
  Vec2 at = anchor;
  for (const double shift : {0.0, 1.0, -1.0, 2.0, -2.0}) {
    const Vec2 candidate = anchor + Vec2(0.0, shift * height);
    if (free(box_at(candidate))) {
      at = candidate;
      break;
    }
  }
  mark(LayoutBox::Kind::label, write(line, style, at, align_x));
}

void Canvas::mark(LayoutBox::Kind kind, const Rect& box) const {
  const Rect clipped{box.min.cwiseMax(Vec2::Zero()),
                     box.max.cwiseMin(Vec2(size.width, size.height))};
  if (clipped.min.x() >= clipped.max.x() || clipped.min.y() >= clipped.max.y()) return;  // off the frame
  draw.mark(kind, clipped);
}

double panel_padding(const Style& style) { return 0.6 * style.margin; }

Vec2 corner_position(const Canvas& c, Corner corner, const Vec2& size) {
  return corner_position(c.style.drawing_area(c.size, c.overlays.has(Overlay::axes)), corner, size);
}

Vec2 corner_position(const Rect& area, Corner corner, const Vec2& size) {
  switch (corner) {
    case Corner::top_right:
      return {area.max.x() - size.x(), area.min.y()};
    case Corner::bottom_left:
      return {area.min.x(), area.max.y() - size.y()};
    case Corner::bottom_right:
      return area.max - size;
    case Corner::top_left:
      break;
  }
  return area.min;
}

void draw_text_box(const Canvas& c, const Rect& box) {
  const std::vector<Vec2> corners{box.min, Vec2(box.max.x(), box.min.y()), box.max,
                                  Vec2(box.min.x(), box.max.y())};
  c.draw.fill_convex(corners, with_alpha(palette::white, 230));
  c.draw.stroke_convex(corners, c.style.unit, palette::grid);
}

void paint_text(const Frame& frame, Canvas& canvas) {
  paint_top_bar(frame, canvas);
  for (const Panel& p : frame.panels) paint_panel(canvas, p);
}

}  // namespace lamina::render
