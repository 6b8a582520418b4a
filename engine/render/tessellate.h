// Shapes as triangles, in pixels. Every count and offset depends only on the input, so the same
// frame always gives the same triangles (deterministic frames).
#pragma once

#include <array>
#include <vector>

#include "render/mesh.h"

namespace lamina::render {

// The corners of a regular polygon approximating a circle; the count grows with the radius.
std::vector<Vec2> circle_points(const Vec2& centre, double radius);

// An arrow's parts: a shaft (a segment `width` wide) and a triangular head, whose tip is `to`;
// not drawn when shorter than a pixel. The head is 4.5 shaft widths long, at most 45 % of a
// short arrow. Every output draws arrows from these (tessellate, vector_output).
struct ArrowShape {
  bool drawn = false;
  Vec2 shaft_from = Vec2::Zero(), shaft_to = Vec2::Zero();
  std::array<Vec2, 3> head{};  // tip, then the base's two corners
};
ArrowShape arrow_shape(const Vec2& from, const Vec2& to, double width);

// The dashes of a polyline, `dash` on and 0.7 dash off, as segments.
std::vector<std::array<Vec2, 2>> dashes(const std::vector<Vec2>& points, double dash);

// A convex polygon, filled.
void fill_convex(Mesh& mesh, const std::vector<Vec2>& polygon, Colour colour);
// The outline of a convex polygon, `width` wide, centred on the edges, with mitred corners.
void stroke_convex(Mesh& mesh, const std::vector<Vec2>& polygon, double width, Colour colour);
// A straight line `width` wide with square ends.
void stroke_segment(Mesh& mesh, const Vec2& a, const Vec2& b, double width, Colour colour);
// A polyline with round joins; dashed in dashes of `dash` pixels when dash > 0.
void stroke_polyline(Mesh& mesh, const std::vector<Vec2>& points, double width, Colour colour,
                     double dash = 0.0);
// A filled disc.
void fill_disc(Mesh& mesh, const Vec2& centre, double radius, Colour colour);
// A filled disc inside a ring `ring_width` wide, centred on the circle of `radius` (small
// markers: two fills are fewer triangles than a fill and a stroke).
void fill_ringed_disc(Mesh& mesh, const Vec2& centre, double radius, Colour fill, double ring_width,
                      Colour ring);
// An arrow from `from` to `to` with a triangular head; nothing when shorter than a pixel.
void draw_arrow(Mesh& mesh, const Vec2& from, const Vec2& to, double width, Colour colour);

}  // namespace lamina::render
