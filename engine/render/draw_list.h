// One frame as drawing commands, in pixels (origin top left, y down), in the order the painters
// issue them (later on top): the one drawing every output format is made from. The OpenGL path
// tessellates it into triangles for PNG (tessellate(), below); Cairo writes it as SVG or PDF
// (vector_output.h), shapes as paths and text as text. A change to the look is made once, in
// the painters (paint.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "render/camera.h"
#include "render/mesh.h"
#include "render/typesetter.h"

namespace lamina::render {

struct DrawCommand {
  enum class Kind {
    fill_convex,    // points: a convex polygon, filled with `colour`
    stroke_convex,  // points: its outline, `width` wide, centred on the edges, mitred
    segment,        // points: a, b; a line `width` wide with square ends
    polyline,       // points; `width` wide with round joins, in dashes of `dash` pixels if > 0
    disc,           // points: the centre; `radius`
    ringed_disc,    // points: the centre; `radius`, filled, in a ring `ring_width` of `ring`
    arrow,          // points: from, to; a shaft `width` wide and a triangular head
    text            // points: the baseline's left end; `text` in `style`
  };
  Kind kind = Kind::fill_convex;
  std::vector<Vec2> points;
  Colour colour;
  double width = 0.0;
  double radius = 0.0;
  double dash = 0.0;
  double ring_width = 0.0;
  Colour ring;
  std::string text;
  TextStyle style;
};

// Where the painters put what must not hide the scene (slides' layout: docs/slides.md): each
// body's bounding box as drawn, the legend's and every panel's box, each label's text box; in
// pixels, clipped to the frame.
struct LayoutBox {
  enum class Kind { body, legend, panel, label };
  Kind kind = Kind::body;
  Rect rect;
};

// The boxes that overlap where they must not: a legend or panel over a body, a label, or each
// other, and two labels over each other. Each as "legend over body 2".
std::vector<std::string> layout_overlaps(const std::vector<LayoutBox>& boxes);

class DrawList {
 public:
  void fill_convex(const std::vector<Vec2>& polygon, Colour colour);
  void stroke_convex(const std::vector<Vec2>& polygon, double width, Colour colour);
  void stroke_segment(const Vec2& a, const Vec2& b, double width, Colour colour);
  void stroke_polyline(const std::vector<Vec2>& points, double width, Colour colour, double dash = 0.0);
  void fill_disc(const Vec2& centre, double radius, Colour colour);
  void fill_ringed_disc(const Vec2& centre, double radius, Colour fill, double ring_width, Colour ring);
  void draw_arrow(const Vec2& from, const Vec2& to, double width, Colour colour);
  // One line of text with its baseline starting at `origin` (Typesetter::draw's rounding).
  void text(std::string_view line, const TextStyle& style, const Vec2& origin);

  // Records a box of the layout (not drawn).
  void mark(LayoutBox::Kind kind, const Rect& rect) { layout_.push_back({kind, rect}); }

  const std::vector<DrawCommand>& commands() const { return commands_; }
  const std::vector<LayoutBox>& layout() const { return layout_; }

 private:
  DrawCommand& add(DrawCommand::Kind kind, std::vector<Vec2> points, Colour colour);
  std::vector<DrawCommand> commands_;
  std::vector<LayoutBox> layout_;
};

// The OpenGL path: every command as triangles (tessellate.h) and glyph rectangles, in order.
void tessellate(const DrawList& list, Mesh& mesh, Typesetter& text);

}  // namespace lamina::render
