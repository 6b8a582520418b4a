// The legend: one row per thing the frame shows that needs explaining.
#include <algorithm>

#include "language/language.h"
#include "render/paint.h"

namespace lamina::render {
namespace {

using Sample = LegendEntry::Sample;

bool any_moving(const Frame& frame) {
  return std::any_of(frame.bodies.begin(), frame.bodies.end(),
                     [](const Body& b) { return !b.fixed; });
}

bool any_contact(const Frame& frame, Contact::Origin origin) {
  return std::any_of(frame.contacts.begin(), frame.contacts.end(),
                     [origin](const Contact& k) { return k.origin == origin; });
}

bool any_friction(const Frame& frame) {
  return std::any_of(frame.contacts.begin(), frame.contacts.end(),
                     [](const Contact& k) { return k.friction_force != 0.0; });
}

// The frame's own entries, then one per overlay layer that is on and has something to show, in
// the current language.
std::vector<LegendEntry> legend_entries(const Frame& frame, const Overlays& on) {
  std::vector<LegendEntry> entries = frame.legend;
  const bool contacts = !frame.contacts.empty();
  auto add = [&](bool shown, Sample sample, Colour colour, const char* text) {
    if (shown) entries.push_back({sample, colour, text});
  };
  add(on.has(Overlay::velocities) && any_moving(frame), Sample::arrow, layer_colour::velocity,
      tr("velocity v"));
  add(on.has(Overlay::centres) && any_moving(frame), Sample::centre, palette::ink,
      tr("centre of mass x"));
  add(on.has(Overlay::contacts) && any_contact(frame, Contact::Origin::fresh),
      Sample::fresh_contact, layer_colour::fresh_contact, tr("new point (no λ from before)"));
  add(on.has(Overlay::contacts) && any_contact(frame, Contact::Origin::refound),
      Sample::refound_contact, layer_colour::fresh_contact, tr("re-found point (warm-started)"));
  add(on.has(Overlay::contacts) && any_contact(frame, Contact::Origin::kept),
      Sample::cached_contact, layer_colour::cached_contact, tr("kept point (cache, eq. 5-12)"));
  add(on.has(Overlay::normals) && contacts, Sample::arrow, layer_colour::normal,
      tr("contact normal n"));
  add(on.has(Overlay::forces) && contacts, Sample::arrow, layer_colour::normal_force,
      tr("normal force λn (length ∝ λ)"));
  add(on.has(Overlay::forces) && any_friction(frame), Sample::arrow, layer_colour::friction,
      tr("friction λu"));
  return entries;
}

void draw_sample(const Canvas& c, const LegendEntry& e, const Vec2& left, double width) {
  const Vec2 right = left + Vec2(width, 0.0), middle = left + Vec2(0.5 * width, 0.0);
  switch (e.sample) {
    case Sample::arrow:
      c.draw.draw_arrow(left, right, c.style.arrow, e.colour);
      break;
    case Sample::line:
      c.draw.stroke_segment(left, right, c.style.line, e.colour);
      break;
    case Sample::dashed_line:
      c.draw.stroke_polyline({left, right}, c.style.line, e.colour, 0.3 * width);
      break;
    case Sample::swatch: {
      const Vec2 half(0.3 * width, 0.3 * c.style.text_px);
      const std::vector<Vec2> box{middle - half, middle + Vec2(half.x(), -half.y()), middle + half,
                                  middle + Vec2(-half.x(), half.y())};
      c.draw.fill_convex(box, e.colour);
      c.draw.stroke_convex(box, c.style.outline, palette::ink);
      break;
    }
    case Sample::point:
      draw_point(c, middle, e.colour);
      break;
    case Sample::fresh_contact:
      draw_fresh_contact(c, middle);
      break;
    case Sample::refound_contact:
      draw_refound_contact(c, middle);
      break;
    case Sample::cached_contact:
      draw_cached_contact(c, middle);
      break;
    case Sample::centre:
      draw_centre_mark(c, middle, 0.0);
      break;
  }
}

}  // namespace

void paint_legend(const Frame& frame, Canvas& c) {
  const std::vector<LegendEntry> entries = legend_entries(frame, c.overlays);
  if (entries.empty()) return;
  const double sample = 2.2 * c.style.text_px, gap = 0.5 * c.style.text_px;
  const double row = c.text.metrics(Typeface::sans, c.style.text_px).height * 1.15;
  const double pad = panel_padding(c.style);
  double text_width = 0.0;
  for (const LegendEntry& e : entries) {
    text_width = std::max(text_width, c.text.width(e.text, Typeface::sans, c.style.text_px));
  }
  const Vec2 size(sample + gap + text_width + 2.0 * pad, entries.size() * row + 2.0 * pad);
  const Vec2 corner = corner_position(c, frame.legend_corner, size);
  draw_text_box(c, {corner, corner + size});
  c.mark(LayoutBox::Kind::legend, {corner, corner + size});
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const Vec2 left = corner + Vec2(pad, pad + (i + 0.5) * row);
    draw_sample(c, entries[i], left, sample);
    c.write(entries[i].text, {Typeface::sans, c.style.text_px, palette::ink},
            left + Vec2(sample + gap, 0.0));
  }
}

}  // namespace lamina::render
