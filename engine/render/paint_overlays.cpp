// The switchable layers: velocities, contact points, normals, forces, centres of mass.
#include <cmath>

#include "render/paint.h"
#include "render/tessellate.h"

namespace lamina::render {
namespace {

void paint_velocities(Canvas& c, const Frame& frame) {
  for (const Body& b : frame.bodies) {
    if (b.fixed) continue;
    c.draw.draw_arrow(c.px(b.centre), c.px(b.centre + frame.velocity_scale * b.velocity),
               c.style.arrow, layer_colour::velocity);
  }
}

void paint_normals(Canvas& c, const Frame& frame) {
  const double length = 30.0 * c.style.unit;
  for (const Contact& k : frame.contacts) {
    const Vec2 at = c.px(k.point);
    c.draw.draw_arrow(at, at + length * Vec2(k.normal.x(), -k.normal.y()).normalized(),
               c.style.line, layer_colour::normal);
  }
}

// Normal force λ n and friction λ u at each contact, drawn from the contact point.
void paint_forces(Canvas& c, const Frame& frame) {
  for (const Contact& k : frame.contacts) {
    const Vec2 at = c.px(k.point);
    c.draw.draw_arrow(at, c.px(k.point + frame.force_scale * k.normal_force * k.normal),
               c.style.arrow, layer_colour::normal_force);
    c.draw.draw_arrow(at, c.px(k.point + frame.force_scale * k.friction_force * k.tangent),
               c.style.arrow, layer_colour::friction);
  }
}

void paint_contacts(Canvas& c, const Frame& frame) {
  for (const Contact& k : frame.contacts) {
    switch (k.origin) {
      case Contact::Origin::fresh:
        draw_fresh_contact(c, c.px(k.point));
        break;
      case Contact::Origin::refound:
        draw_refound_contact(c, c.px(k.point));
        break;
      case Contact::Origin::kept:
        draw_cached_contact(c, c.px(k.point));
        break;
    }
  }
}

void paint_centres(Canvas& c, const Frame& frame) {
  for (const Body& b : frame.bodies) {
    if (!b.fixed) draw_centre_mark(c, c.px(b.centre), b.angle);
  }
}

}  // namespace

void draw_point(const Canvas& c, const Vec2& at, Colour colour) {
  c.draw.fill_ringed_disc(at, c.style.marker, colour, 0.6 * c.style.outline, palette::ink);
}

void draw_fresh_contact(const Canvas& c, const Vec2& at) {
  draw_point(c, at, layer_colour::fresh_contact);
}

void draw_cached_contact(const Canvas& c, const Vec2& at) {
  const double r = 1.35 * c.style.marker;
  const std::vector<Vec2> diamond{at + Vec2(r, 0), at + Vec2(0, r), at - Vec2(r, 0),
                                  at - Vec2(0, r)};
  c.draw.fill_convex(diamond, layer_colour::cached_contact);
  c.draw.stroke_convex(diamond, 0.6 * c.style.outline, palette::ink);
}

void draw_refound_contact(const Canvas& c, const Vec2& at) {
  draw_cached_contact(c, at);
  c.draw.fill_ringed_disc(at, 0.75 * c.style.marker, layer_colour::fresh_contact,
                   0.5 * c.style.outline, palette::ink);
}

// The centre-of-mass symbol: a dark disc with two opposite white quarters, turning with the body.
void draw_centre_mark(const Canvas& c, const Vec2& at, double angle) {
  const double r = 1.2 * c.style.marker;
  c.draw.fill_disc(at, r, palette::ink);
  const std::vector<Vec2> rim = circle_points(at, r - 0.6 * c.style.outline);
  const std::size_t n = rim.size(), quarter = n / 4;
  // Pixel angles run clockwise (y down), so a body angle θ is −θ on screen.
  const auto first =
      static_cast<std::size_t>(std::lround(std::fmod(-angle / (2 * M_PI) + 2.0, 1.0) * n)) % n;
  for (std::size_t q : {first + quarter, first + 3 * quarter}) {
    std::vector<Vec2> sector{at};
    for (std::size_t i = 0; i <= quarter; ++i) sector.push_back(rim[(q + i) % n]);
    c.draw.fill_convex(sector, palette::white);
  }
}

void paint_overlays(const Frame& frame, Canvas& canvas) {
  if (canvas.overlays.has(Overlay::velocities)) paint_velocities(canvas, frame);
  if (canvas.overlays.has(Overlay::forces)) paint_forces(canvas, frame);
  if (canvas.overlays.has(Overlay::normals)) paint_normals(canvas, frame);
  if (canvas.overlays.has(Overlay::contacts)) paint_contacts(canvas, frame);
  if (canvas.overlays.has(Overlay::centres)) paint_centres(canvas, frame);
}

}  // namespace lamina::render
