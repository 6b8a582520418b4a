// What one frame shows: a plain description that tutorials fill from engine state.
//
// World items are in metres, in the x–y plane with y up; the renderer never sees the engine.
// 3D items (Arrow3, Path3, Point3, Label3) are drawn by the frame's oblique projection.
// Which overlay layer an item belongs to decides whether --overlay shows it.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "kinematics/math_types.h"
#include "render/colour.h"
#include "render/oblique.h"
#include "render/overlay.h"

namespace lamina::render {


// A rigid body's outline: a box, a circle, a convex polygon or a capsule, with a mark that shows
// its rotation.
struct Body {
  enum class Shape { box, circle, polygon, capsule };
  Shape shape = Shape::box;
  Vec2 centre = Vec2::Zero();   // centre of mass x, in m
  double angle = 0.0;           // θ about z, in rad
  Vec2 half_extents{0.5, 0.5};  // box: half width and half height, in m
  double radius = 0.5;          // circle, capsule: radius, in m
  double length = 1.0;          // capsule: between its caps' centres, along its x axis, in m
  std::vector<Vec2> vertices;   // polygon: counter-clockwise, body frame about `centre`, in m
  Colour fill = tint(palette::sky_blue, 0.35);
  Vec2 velocity = Vec2::Zero();  // v, in m/s (the velocities overlay)
  bool fixed = false;            // a static body: no centre-of-mass mark, no velocity
};

// The ground: the half-plane behind a line through `point`, with outward normal `normal`.
struct Ground {
  Vec2 point = Vec2::Zero();    // a point on the surface, in m
  Vec2 normal = Vec2::UnitY();  // unit outward normal
};

// A joint: a link from a to b with a pin at each end.
struct Joint {
  Vec2 a = Vec2::Zero();  // anchor on the first body (or the world), in m
  Vec2 b = Vec2::Zero();  // anchor on the second body, in m
};

// A contact point with its normal and the forces the solver found (chapter 4).
struct Contact {
  Vec2 point = Vec2::Zero();     // contact point, in m
  Vec2 normal = Vec2::UnitY();   // unit normal n, pointing into the body it pushes
  double normal_force = 0.0;     // λ of the contact row, in N
  Vec2 tangent = Vec2::UnitX();  // unit tangent u of the friction row
  double friction_force = 0.0;   // λ of the friction row along u, in N
  // Where the point comes from (Fig 4-2..4-5): found this step with no λ from before (new), found
  // this step where a cached point was and warm-started from it (re-found), or re-placed from
  // the cache without being found (kept).
  enum class Origin { fresh, refound, kept };
  Origin origin = Origin::fresh;
};

// An arrow from `from` to `to`, with an optional label at its tip.
struct Arrow {
  Vec2 from = Vec2::Zero();  // tail, in m
  Vec2 to = Vec2::Zero();    // tip, in m
  Colour colour = palette::ink;
  std::string label;             // drawn next to the tip; may be empty
  std::optional<Overlay> layer;  // shown only with this overlay; always when empty
};

// A polyline: a trail, an analytic curve, a divider.
struct Path {
  std::vector<Vec2> points;  // in m
  Colour colour = palette::grey;
  bool dashed = false;
};

// Text anchored at a world point; `align` says which end of the text sits on the point.
struct Label {
  enum class Align { left, centre, right };
  Vec2 at = Vec2::Zero();  // in m
  std::string text;        // UTF-8
  Colour colour = palette::ink;
  Align align = Align::left;
};

// 3D items: points in m with a z, drawn where Frame::projection puts them (oblique.h).

// An arrow in space from `from` to `to`, with an optional label at its tip.
struct Arrow3 {
  Vec3 from = Vec3::Zero();  // tail, in m
  Vec3 to = Vec3::Zero();    // tip, in m
  Colour colour = palette::ink;
  std::string label;  // drawn next to the tip; may be empty
};

// A polyline in space: an axis, a circle of rotation, the edges of a body.
struct Path3 {
  std::vector<Vec3> points;  // in m
  Colour colour = palette::grey;
  bool dashed = false;
};

// A marked point in space (a particle, a point where a force is applied), with a name beside it.
struct Point3 {
  Vec3 at = Vec3::Zero();  // in m
  Colour colour = palette::ink;
  std::string label;  // drawn to the right of the mark; may be empty
};

// Text anchored at a point in space; `align` says which end of the text sits on the point.
struct Label3 {
  Vec3 at = Vec3::Zero();  // in m
  std::string text;        // UTF-8
  Colour colour = palette::ink;
  Label::Align align = Label::Align::left;
};

// A corner of the drawing area (below the caption), where panels and the legend sit.
enum class Corner { top_left, top_right, bottom_left, bottom_right };

// A block of text lines in a corner of the frame: a title, then lines in a monospaced face.
struct Panel {
  Corner corner = Corner::top_left;
  std::string title;  // drawn in bold, in title_colour; may be empty
  Colour title_colour = palette::ink;
  std::vector<std::string> lines;  // UTF-8, one per row
};

// A legend row: a small sample of what the entry names, then its text.
struct LegendEntry {
  enum class Sample {
    arrow,
    line,
    dashed_line,
    swatch,
    point,  // a Point3's mark, in the entry's colour
    fresh_contact,
    refound_contact,
    cached_contact,
    centre
  };
  Sample sample = Sample::line;
  Colour colour = palette::ink;
  std::string text;
};

struct Frame {
  std::string caption;  // top left, e.g. "Fig 2-1  Thrown box (eq. 2-3..2-6)"
  std::string status;   // top right, e.g. "t = 0.500 s   step 30" (the renderer writes t and the step
                        // when a scene leaves it empty)

  std::vector<Ground> grounds;
  std::vector<Path> paths;
  std::vector<Body> bodies;
  std::vector<Joint> joints;
  std::vector<Contact> contacts;
  std::vector<Arrow> arrows;
  std::vector<Label> labels;
  ObliqueProjection projection;  // how the 3D items below are drawn
  std::vector<Path3> paths3;
  std::vector<Arrow3> arrows3;
  std::vector<Point3> points3;
  std::vector<Label3> labels3;
  std::vector<Panel> panels;                    // at most one per corner
  std::vector<LegendEntry> legend;              // the scene's own entries; overlays add theirs
  Corner legend_corner = Corner::bottom_right;  // not a corner a panel uses

  double velocity_scale = 0.25;  // arrow length per speed, in m per m/s
  double force_scale = 0.01;     // arrow length per force λ, in m per N
};

}  // namespace lamina::render
