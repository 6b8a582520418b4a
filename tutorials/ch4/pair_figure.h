// The pair of polygons the GJK and EPA scenes (gjk_scene.h, epa_scene.h) run on, and the figure
// both draw it in: A a hexagon and B a triangle (body 1 and body 2 of the other chapter-4 frames),
// drawn twice, the shapes where they are (left) and their Minkowski difference D = B − A, the
// hull of every b_j − a_i, about the origin O (right). With it what both scenes write: the names
// of the vertices a_i, b_j and of D's points b_j − a_i, the simplex drawn on D, the panel of
// numbers, and the separating axis test EPA's depth is set beside.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "app/harness/explanation.h"
#include "contact/gjk.h"
#include "contact/shape.h"
#include "render/frame.h"

namespace lamina::ch4 {

// D's fill, and the algorithms' points each in a colour of their own: `kept` the simplex or the
// polytope, `nearest` their point or edge nearest O, `added` the support point and its vertices.
inline const render::Colour d_fill = tint(render::palette::bluish_green, 0.2);
inline const render::Colour kept = render::palette::blue;
inline const render::Colour nearest = render::palette::reddish_purple;
inline const render::Colour added = render::palette::vermillion;

// "a₂": a vertex's name, its index as subscript digits.
std::string vertex_name(char body, int index);
// "b₂−a₀": a point of D by the two vertices it is the difference of.
std::string point_name(const SimplexVertex& v);

// "(x, y)" with fixed decimals, and the same as JSON: one point, or rows of them.
std::string planar(const Vec2& v);
tutorial::Json json_of(const Vec2& v);
tutorial::Json rows_of(const std::vector<Vec2>& points);

// The separating axis test on two polygons: over every edge's outward normal m of both, the
// overlap of their projections min(max_A m·v, max_B m·v) − max(min_A m·v, min_B m·v). The
// least overlap is the depth (> 0: they overlap), its edge the axis.
struct SeparatingAxis {
  double overlap = std::numeric_limits<double>::infinity();  // the least overlap, in m
  Vec2 normal = Vec2::UnitY();                               // its edge's outward normal
  std::string edge;                                          // that edge, e.g. "a₂a₃"
};

SeparatingAxis least_overlap(const Convex& a, const Convex& b);

// One pair drawn twice: the shapes where they are (left) and D = B − A about O (right).
class PairFigure {
 public:
  // A where every scene has it, B at `b_centre`; O drawn at `origin`. `name_side`: −1 names O on
  // its left, +1 on its right (clear of the lines that leave O).
  PairFigure(const Vec2& b_centre, const Vec2& origin, double name_side);

  const Convex& a() const { return cores_[0]; }
  const Convex& b() const { return cores_[1]; }
  const Shape& shape(int k) const { return shapes_[static_cast<std::size_t>(k)]; }
  const Pose2& pose(int k) const { return poses_[static_cast<std::size_t>(k)]; }
  const std::vector<Vec2>& difference() const { return difference_; }
  int difference_count() const { return static_cast<int>(differences_.size()); }

  // The b_j − a_i nearest w (the algorithms' points of D are differences of vertices).
  const SimplexVertex& source(const Vec2& w) const;

  // A and B, named; with `names` their vertices' names, those of `marked` in the support
  // point's colour with the arrow b_j − a_i between them.
  void draw_shapes(render::Frame& frame, const SimplexVertex* marked, bool names) const;
  // D filled, named below its top, and O.
  void draw_difference(render::Frame& frame) const;

  // Where a point w of D is drawn.
  Vec2 at(const Vec2& w) const { return origin_ + w; }

  // A polyline through points of D (closed: back to the first), drawn over D's fill.
  void stroke(render::Frame& frame, const std::vector<Vec2>& w, render::Colour colour, bool closed,
              bool dashed) const;
  // A marked point of D with its name.
  void mark(render::Frame& frame, const Vec2& w, render::Colour colour,
            const std::string& name) const;

 private:
  std::array<Shape, 2> shapes_;             // A and B, vertices about their centroids
  std::array<Pose2, 2> poses_;              // where they are, world frame
  std::array<Convex, 2> cores_;             // their vertices a_i, b_j, world frame, in m
  std::vector<SimplexVertex> differences_;  // every b_j − a_i with the two vertices
  std::vector<Vec2> difference_;            // D's vertices, counter-clockwise, in m
  Vec2 origin_;                             // where O is drawn, in m
  double name_side_;                        // O's name left (−1) or right (+1) of it
};

// A simplex's points of D, and their names "b₀−a₁, b₂−a₁".
std::vector<Vec2> points_of(const Simplex& s);
std::string names_of(const Simplex& s);

// The simplex's points, blue, each named.
void draw_simplex(render::Frame& frame, const PairFigure& figure, const Simplex& s);

// The panel of numbers, bottom left: a title, then one line a number.
render::Panel panel(const std::string& title, std::vector<std::string> lines);

}  // namespace lamina::ch4
