// Painters turn a Frame into drawing commands (draw_list.h) in the lecture style, one layer per
// function, drawn in the order below (later layers on top).
#pragma once

#include "render/draw_list.h"
#include "render/frame.h"
#include "render/style.h"
#include "render/typesetter.h"

namespace lamina::render {

// The colours of the overlay layers, shared by their painters and their legend entries.
namespace layer_colour {
inline constexpr Colour velocity = palette::blue;
inline constexpr Colour normal = palette::ink;
inline constexpr Colour normal_force = palette::bluish_green;
inline constexpr Colour friction = palette::orange;
inline constexpr Colour fresh_contact = palette::vermillion;
inline constexpr Colour cached_contact = palette::reddish_purple;
}  // namespace layer_colour

// What every painter draws with.
struct Canvas {
  DrawList& draw;
  const Camera& camera;
  const Style& style;
  Typesetter& text;
  FrameSize size;
  Overlays overlays;

  Vec2 px(const Vec2& world) const { return camera.to_pixels(world); }
  // Draws one line of text whose vertical middle sits at `anchor.y`; `align_x` 0 puts its left
  // end at anchor.x, 0.5 its middle, 1 its right end.
  // Returns the line's box, ascender to descender.
  Rect write(std::string_view line, const TextStyle& style, const Vec2& anchor,
             double align_x = 0.0) const;
  // The box of a label's line, kept in the layout (draw_list.h).
  void write_label(std::string_view line, const TextStyle& style, const Vec2& anchor,
                   double align_x = 0.0) const;
  // A box of the layout, clipped to the frame.
  void mark(LayoutBox::Kind kind, const Rect& box) const;
};

// The metre grid behind everything (the axes overlay).
void paint_grid(const Frame& frame, Canvas& canvas);
// Ground, paths, bodies with their rotation marks, joints, arrows and labels, then the 3D items
// (paths, arrows, points, labels) through the frame's oblique projection.
void paint_world(const Frame& frame, Canvas& canvas);
// Velocities, contact points, normals, forces and centres of mass, as switched on.
void paint_overlays(const Frame& frame, Canvas& canvas);
// Axis lines, ticks and their labels in metres (the axes overlay).
void paint_axes(const Frame& frame, Canvas& canvas);
// Caption, status line and corner panels.
void paint_text(const Frame& frame, Canvas& canvas);
// The legend box: the frame's own entries, then those of the overlays it shows.
void paint_legend(const Frame& frame, Canvas& canvas);

// A light box behind a block of text (panels, legend), and the gap inside its border.
void draw_text_box(const Canvas& canvas, const Rect& box);
double panel_padding(const Style& style);
// The top-left pixel of a block of `size` placed in a corner of the drawing area.
Vec2 corner_position(const Canvas& canvas, Corner corner, const Vec2& size);
// The same in a given drawing area (Style::drawing_area).
Vec2 corner_position(const Rect& area, Corner corner, const Vec2& size);

// Markers shared by the overlays, the 3D points and the legend, centred on a pixel.
void draw_point(const Canvas& canvas, const Vec2& at, Colour colour);  // a disc in an ink ring
void draw_fresh_contact(const Canvas& canvas, const Vec2& at);
void draw_cached_contact(const Canvas& canvas, const Vec2& at);
// A re-found point: the kept point's diamond with the new point's disc inside it.
void draw_refound_contact(const Canvas& canvas, const Vec2& at);
void draw_centre_mark(const Canvas& canvas, const Vec2& at, double angle);

}  // namespace lamina::render
