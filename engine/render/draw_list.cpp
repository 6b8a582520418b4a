#include "render/draw_list.h"

#include <utility>

#include "render/tessellate.h"

namespace lamina::render {

DrawCommand& DrawList::add(DrawCommand::Kind kind, std::vector<Vec2> points, Colour colour) {
  DrawCommand& c = commands_.emplace_back();
  c.kind = kind;
  c.points = std::move(points);
  c.colour = colour;
  return c;
}

void DrawList::fill_convex(const std::vector<Vec2>& polygon, Colour colour) {
  add(DrawCommand::Kind::fill_convex, polygon, colour);
}

void DrawList::stroke_convex(const std::vector<Vec2>& polygon, double width, Colour colour) {
  add(DrawCommand::Kind::stroke_convex, polygon, colour).width = width;
}

void DrawList::stroke_segment(const Vec2& a, const Vec2& b, double width, Colour colour) {
  add(DrawCommand::Kind::segment, {a, b}, colour).width = width;
}

void DrawList::stroke_polyline(const std::vector<Vec2>& points, double width, Colour colour,
                               double dash) {
  DrawCommand& c = add(DrawCommand::Kind::polyline, points, colour);
  c.width = width;
  c.dash = dash;
}

void DrawList::fill_disc(const Vec2& centre, double radius, Colour colour) {
  add(DrawCommand::Kind::disc, {centre}, colour).radius = radius;
}

void DrawList::fill_ringed_disc(const Vec2& centre, double radius, Colour fill, double ring_width,
                                Colour ring) {
  DrawCommand& c = add(DrawCommand::Kind::ringed_disc, {centre}, fill);
  c.radius = radius;
  c.ring_width = ring_width;
  c.ring = ring;
}

void DrawList::draw_arrow(const Vec2& from, const Vec2& to, double width, Colour colour) {
  add(DrawCommand::Kind::arrow, {from, to}, colour).width = width;
}

void DrawList::text(std::string_view line, const TextStyle& style, const Vec2& origin) {
  DrawCommand& c = add(DrawCommand::Kind::text, {origin}, style.colour);
  c.text = std::string(line);
  c.style = style;
}

std::vector<std::string> layout_overlaps(const std::vector<LayoutBox>& boxes) {
  using Kind = LayoutBox::Kind;
  const auto name = [](Kind k) {
    switch (k) {
      case Kind::body: return "body";
      case Kind::legend: return "legend";
      case Kind::panel: return "panel";
      case Kind::label: return "label";
    }
    return "box";
  };
  // open rectangles: boxes that only touch along an edge do not overlap
  const auto overlap = [](const Rect& a, const Rect& b) {
    return a.min.x() < b.max.x() && b.min.x() < a.max.x() && a.min.y() < b.max.y() && b.min.y() < a.max.y();
  };
  const auto text_box = [](Kind k) { return k == Kind::legend || k == Kind::panel; };
  std::vector<std::string> found;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const Kind a = boxes[i].kind, b = boxes[j].kind;
      // a legend or panel must hide nothing; labels must not cover each other (a label beside
      // its body may touch it: that is where it belongs)
      const bool matters = text_box(a) || text_box(b) || (a == Kind::label && b == Kind::label);
      if (!matters || !overlap(boxes[i].rect, boxes[j].rect)) continue;
      found.push_back(std::string(name(a)) + " " + std::to_string(i) + " and " + name(b) + " " +
                      std::to_string(j) + " overlap");
    }
  }
  return found;
}

void tessellate(const DrawList& list, Mesh& mesh, Typesetter& text) {
  using Kind = DrawCommand::Kind;
  for (const DrawCommand& c : list.commands()) {
    switch (c.kind) {
      case Kind::fill_convex: fill_convex(mesh, c.points, c.colour); break;
      case Kind::stroke_convex: stroke_convex(mesh, c.points, c.width, c.colour); break;
      case Kind::segment: stroke_segment(mesh, c.points[0], c.points[1], c.width, c.colour); break;
      case Kind::polyline: stroke_polyline(mesh, c.points, c.width, c.colour, c.dash); break;
      case Kind::disc: fill_disc(mesh, c.points[0], c.radius, c.colour); break;
      case Kind::ringed_disc:
        fill_ringed_disc(mesh, c.points[0], c.radius, c.colour, c.ring_width, c.ring);
        break;
      case Kind::arrow: draw_arrow(mesh, c.points[0], c.points[1], c.width, c.colour); break;
      case Kind::text: text.draw(mesh, c.text, c.style, c.points[0]); break;
    }
  }
}

}  // namespace lamina::render
