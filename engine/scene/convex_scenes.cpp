#include "scene/convex_scenes.h"

#include <algorithm>
#include <cmath>

#include "scene/builtin_parts.h"

namespace lamina::builtin {
namespace {

// A regular hexagon of circumradius r with a flat bottom and top (vertices at 0°, 60°, …),
// about its centre.
ShapeDescription hexagon(double r) {
  ShapeDescription shape;
  shape.type = ShapeType::polygon;
  for (int k = 0; k < 6; ++k) shape.vertices.push_back(r * Vec2(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)));
  return shape;
}

}  // namespace

// A static wedge of slope θ = 35° (a right triangle 6 m long, 6 tan θ high) on the ground, and a
// hexagon lying on its slope near the top with a face on it: on a slope steeper than 30° a
// hexagon tips over its lower corner (its centre passes that corner), so it tumbles down.
Scene wedge_ramp() {
  const double theta = 35.0 * M_PI / 180.0, run = 6.0, r = 0.4;
  BodyDescription wedge;
  wedge.name = "wedge";
  wedge.shape.type = ShapeType::polygon;
  wedge.shape.vertices = {{0.0, 0.0}, {run, 0.0}, {0.0, run * std::tan(theta)}};
  wedge.position = {-3.0, 0.0};  // the vertices' origin: the wedge's lower-left corner
  wedge.is_static = true;
  BodyDescription hex;
  hex.name = "hexagon";
  hex.shape = hexagon(r);
  // A face on the slope: turned by −θ, its centre the apothem above the slope's point 1.2 m
  // (along the slope) from the top.
  hex.angle = -theta;
  const Vec2 down_slope(std::cos(theta), -std::sin(theta)), normal(std::sin(theta), std::cos(theta));
  const Vec2 top = wedge.position + wedge.shape.vertices[2];
  hex.position = top + 1.2 * down_slope + r * std::sqrt(3.0) / 2.0 * normal;
  return with({ground(), wedge, hex});
}

// Thirty capsules (ρ = 0.15 m, l = 0.9 m) dropped in six layers between two walls, each layer
// turned a little from the one below, onto the ground.
Scene capsule_pile() {
  std::vector<BodyDescription> bodies = {ground()};
  for (const double x : {-3.2, 3.2}) {
    BodyDescription wall = box(x < 0 ? "left wall" : "right wall", {x, 2.5}, {0.2, 2.5});
    wall.is_static = true;
    bodies.push_back(wall);
  }
  for (int layer = 0; layer < 6; ++layer) {
    for (int i = 0; i < 5; ++i) {
      BodyDescription c;
      c.name = "c" + std::to_string(layer) + "_" + std::to_string(i);
      c.shape.type = ShapeType::capsule;
      c.shape.radius = 0.15;
      c.shape.length = 0.9;
      c.position = {-2.4 + 1.2 * i + (layer % 2 == 0 ? 0.0 : 0.3), 0.5 + 0.55 * layer};
      c.angle = (layer % 2 == 0 ? 0.25 : -0.25) + 0.1 * (i - 2);
      bodies.push_back(c);
    }
  }
  return with(bodies);
}

// A pyramid of regular hexagons (circumradius 0.5 m, flat bottom) packed as a honeycomb: the
// base's hexagons stand 1.5 m apart on the ground, and each row above fills the gaps of the row
// below, face against face, so row k has rows − k hexagons and its centres lie k apothems higher.
Scene hexagon_pyramid(double n) {
  const int rows = static_cast<int>(n);
  const double r = 0.5, apothem = r * std::sqrt(3.0) / 2.0;
  std::vector<BodyDescription> bodies = {ground(std::max(20.0, rows * 1.5 * r + 5.0))};
  for (int row = 0; row < rows; ++row) {
    const int count = rows - row;
    for (int i = 0; i < count; ++i) {
      BodyDescription h;
      h.name = "r" + std::to_string(row) + "h" + std::to_string(i);
      h.shape = hexagon(r);
      h.position = {(i - 0.5 * (count - 1)) * 3.0 * r, apothem * (row + 1)};
      bodies.push_back(h);
    }
  }
  return with(bodies);
}

std::string hexagon_pyramid_description(double n, Wording words) {
  const int rows = static_cast<int>(n);
  return fill(words(msg("a honeycomb pyramid of {0} hexagons, {1} in its base")),
              {std::to_string(rows * (rows + 1) / 2), std::to_string(rows)});
}

}  // namespace lamina::builtin
