#include "ch4/epa_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "app/harness/format.h"
#include "ch4/pair_figure.h"
#include "ch4/pair_scene.h"
#include "contact/gjk.h"
#include "contact/narrow_phase.h"
#include "language/language.h"

namespace lamina::ch4 {
namespace {

namespace palette = render::palette;
using Align = render::Label::Align;
using Sample = render::LegendEntry::Sample;
using tutorial::fixed;
using tutorial::Json;

const Vec2 b_overlapping(-2.25, 1.7);  // B's centroid, in m
const Vec2 epa_origin(1.5, -0.1);      // where O is drawn: D right of the shapes, above the legend

constexpr double normal_arrow = 0.5;  // EPA's normal m drawn this long, in m

// EPA on the pair overlapping: GJK's last triangle, one frame per iteration, the answer.
class Epa : public PairScene {
 public:
  Epa()
      : PairScene("epa", "EPA", PairFigure(b_overlapping, epa_origin, 1.0)),
        overlap_(gjk(figure().a(), figure().b())),
        result_(epa(figure().a(), figure().b(), overlap_, &record_)),
        axis_(least_overlap(figure().a(), figure().b())),
        contact_(collide_convex(figure().shape(0), figure().pose(0), figure().shape(1),
                                figure().pose(1), CachedPoints{}, TieRule{})) {}

 private:
  int iterations() const override { return static_cast<int>(record_.size()); }
  const EpaIteration& at(int k) const { return record_[static_cast<std::size_t>(k - 1)]; }

  // The nearest edge's ends.
  static std::array<Vec2, 2> edge_of(const EpaIteration& it) {
    const std::size_t k = static_cast<std::size_t>(it.nearest_edge);
    return {it.polytope[k], it.polytope[(k + 1) % it.polytope.size()]};
  }
  // How far s lies beyond the nearest edge: m · s − distance.
  static double gain(const EpaIteration& it) { return it.normal.dot(it.support) - it.distance; }
  std::string edge_name(const EpaIteration& it) const {
    const auto [p, q] = edge_of(it);
    return fill(tr("{0} to {1}"), {point_name(figure().source(p)), point_name(figure().source(q))});
  }
  // EPA stops when s is no farther out than the edge (to 1e-10 max(1, d), gjk.cpp) or is a
  // point the polytope already has.
  std::string verdict(const EpaIteration& it) const {
    const bool held = std::any_of(it.polytope.begin(), it.polytope.end(),
                                  [&](const Vec2& p) { return (p - it.support).norm() <= 1e-12; });
    if (held) return tr("stop: s is a vertex already");
    if (gain(it) <= 1e-10 * std::max(1.0, it.distance)) return tr("stop: the edge is D's own");
    return tr("go on: s goes in");
  }

  void draw_start(render::Frame& frame) const override {
    frame.caption = tr("EPA · B moved into A: GJK's simplex is a triangle around O, the cores overlap");
    figure().draw_shapes(frame, nullptr, true);
    draw_simplex(frame, figure(), overlap_.simplex);
    frame.panels.push_back(
        panel(fill(tr("GJK on the overlapping pair: {0} iterations"), {std::to_string(overlap_.iterations)}),
              {fill(tr("its simplex {0}"), {names_of(overlap_.simplex)}),
               tr("holds O: the cores overlap, the distance is 0"),
               tr("GJK cannot tell how deep: EPA grows this triangle"),
               tr("to D's edge nearest O, whose distance is the depth")}));
    frame.legend = {{Sample::swatch, d_fill, "D = B − A"},
                    {Sample::point, kept, tr("GJK's last simplex")}};
  }

  void draw_iteration(render::Frame& frame, int k) const override {
    const EpaIteration& it = at(k);
    const auto [p, q] = edge_of(it);
    const SimplexVertex& s = figure().source(it.support);
    frame.caption = fill(
        tr("EPA iteration {0} · the polytope's edge nearest O, pushed out to D's support point along its normal"),
        {std::to_string(k)});
    figure().draw_shapes(frame, &s, true);
    figure().stroke(frame, it.polytope, kept, true, false);
    for (const Vec2& w : it.polytope) {  // the nearest edge's ends named (the panel names them too)
      figure().mark(frame, w, kept, w == p || w == q ? point_name(figure().source(w)) : "");
    }
    figure().stroke(frame, {p, q}, nearest, false, false);
    const Vec2 foot = it.distance * it.normal;  // the edge's point nearest O
    figure().stroke(frame, {Vec2::Zero(), foot}, palette::ink, false, true);
    frame.arrows.push_back({figure().at(foot), figure().at(foot + normal_arrow * it.normal),
                            palette::ink, "m", std::nullopt});
    if (gain(it) > 1e-10) figure().stroke(frame, {p, it.support, q}, added, false, true);
    figure().mark(frame, it.support, added, "s");
    frame.panels.push_back(
        panel(iteration_title(k),
              {fill(tr("polytope: {0} points of D"), {std::to_string(it.polytope.size())}),
               fill(tr("nearest edge {0}"), {edge_name(it)}),
               fill(tr("its normal m = {0}, distance {1} m"), {planar(it.normal), fixed(it.distance, 4)}),
               "s = s_D(m) = " + point_name(s) + " = " + planar(it.support) + " m",
               fill(tr("m·s − distance = {0} m: {1}"), {fixed(gain(it), 4), verdict(it)}),
               fill(tr("depth in [distance, m·s] = [{0}, {1}] m"),
                    {fixed(it.distance, 4), fixed(it.normal.dot(it.support), 4)})}));
    frame.legend = {{Sample::swatch, d_fill, "D = B − A"},
                    {Sample::point, kept, tr("polytope")},
                    {Sample::line, nearest, tr("its edge nearest O")},
                    {Sample::arrow, palette::ink, tr("m: that edge's outward normal")},
                    {Sample::point, added, "s = s_D(m) = b_j − a_i"}};
  }

  void draw_answer(render::Frame& frame) const override {
    frame.caption = tr("EPA's answer · B moved by depth along n (dashed) only touches A");
    figure().draw_shapes(frame, nullptr, false);
    const Vec2 a = result_.point_a, b = result_.point_b;
    render::Path3 moved{{}, palette::blue, true};  // B's outline moved by depth·n
    for (int j = 0; j <= figure().b().count; ++j) {
      moved.points.push_back(
          lift(figure().b().vertices[j % figure().b().count] + result_.depth * result_.normal));
    }
    frame.paths3.push_back(moved);
    frame.arrows.push_back({b, a, palette::ink, "", std::nullopt});
    frame.points3.push_back({lift(a), nearest, ""});
    frame.points3.push_back({lift(b), nearest, ""});
    frame.labels.push_back({a + Vec2(0.12, 0.0), "a", nearest, Align::left});
    frame.labels.push_back({b + Vec2(-0.12, 0.0), "b", nearest, Align::right});
    frame.labels.push_back({b + Vec2(0.35, -0.2), tr("depth·n"), palette::ink, Align::right});
    const EpaIteration& it = at(iterations());
    figure().stroke(frame, it.polytope, kept, true, false);
    for (const Vec2& w : it.polytope) figure().mark(frame, w, kept, "");
    const auto [p, q] = edge_of(it);
    figure().stroke(frame, {p, q}, nearest, false, false);
    frame.arrows.push_back(
        {figure().at(Vec2::Zero()), figure().at(b - a), nearest, "b − a", std::nullopt});
    frame.panels.push_back(panel(
        fill(tr("EPA ends after {0} iterations"), {std::to_string(iterations())}),
        {
            fill(tr("depth = {0} m along n = −m = {1}"), {fixed(result_.depth, 4), planar(result_.normal)}),
            fill(tr("a = {0} m, A's point deepest in B"), {planar(a)}),
            fill(tr("b = a − depth·n = {0} m"), {planar(b)}),
            fill(tr("separating axes: least overlap {0} m, edge {1}"), {fixed(axis_.overlap, 4), axis_.edge}),
            fill(tr("EPA − SAT = {0} m"), {tutorial::scientific(result_.depth - axis_.overlap)}),
            contact_ ? fill(tr("narrow phase: depth {0} m at b"), {fixed(contact_->depth, 4)})
                     : std::string(tr("narrow phase: depth none")),
        }));
    frame.legend = {{Sample::swatch, d_fill, "D = B − A"},
                    {Sample::point, kept, tr("the last polytope")},
                    {Sample::line, nearest, tr("D's edge nearest O")},
                    {Sample::arrow, nearest, tr("b − a = −depth·n")}};
  }

  tutorial::Section explain_start() const override {
    return {tr("GJK on the overlapping pair"), triangle_quantities()};
  }

  std::vector<tutorial::Quantity> triangle_quantities() const {
    return {{tr("in words"), "", tr("the step"),
             fill(tr("B overlaps A: after {0} iterations GJK's simplex {{1}} is a triangle holding O, so "
                     "the cores overlap. Its distance is 0; EPA starts from this triangle to find the depth."),
                  {std::to_string(overlap_.iterations), names_of(overlap_.simplex)}),
             ""},
            {tr("simplex"), "", tr("GJK's last simplex, a triangle around O"),
             rows_of(points_of(overlap_.simplex)), "m"},
            {tr("iterations"), "", tr("GJK's support points"), overlap_.iterations, ""}};
  }

  std::vector<tutorial::Quantity> iteration_quantities(int k) const override {
    const EpaIteration& it = at(k);
    return {
        {tr("in words"), "", tr("the step"),
         fill(tr("Of the polytope's {0} edges the one nearest O runs {1}, at distance {2} m along its "
                 "outward normal m = {3}. D's support point along m is s = {4} = {5} m, {6} m beyond "
                 "the edge: {7}."),
              {std::to_string(it.polytope.size()), edge_name(it), fixed(it.distance, 4),
               planar(it.normal), point_name(figure().source(it.support)), planar(it.support),
               fixed(gain(it), 4), verdict(it)}),
         ""},
        {tr("polytope"), "", tr("D's points found so far, counter-clockwise"), rows_of(it.polytope), "m"},
        {"m", "", tr("the nearest edge's outward unit normal"), json_of(it.normal), ""},
        {tr("distance"), "", tr("that edge's distance from O: a lower bound on the depth"), it.distance,
         "m"},
        {"s", "", tr("s_D(m), D's point farthest along m"), json_of(it.support), "m"},
        {"m·s", "", tr("an upper bound on the depth"), it.normal.dot(it.support), "m"},
        {tr("m·s − distance"), "", tr("how far s lies beyond the edge (stop at ≤ 1e-10 max(1, distance))"),
         gain(it), "m"}};
  }

  std::vector<tutorial::Quantity> answer_quantities() const override {
    return {
        {tr("in words"), "", tr("the result"),
         fill(tr("EPA's depth {0} m along n = {1}; the separating axis test's least overlap is {2} m "
                 "(edge {3}), {4} m apart. Moving B by depth·n leaves A and B touching."),
              {fixed(result_.depth, 4), planar(result_.normal), fixed(axis_.overlap, 4), axis_.edge,
               tutorial::scientific(std::abs(result_.depth - axis_.overlap))}),
         ""},
        {tr("depth"), "", tr("EPA: the distance of D's edge nearest O"), result_.depth, "m"},
        {"n", "", tr("from A to B, minus that edge's outward normal"), json_of(result_.normal), ""},
        {"a", "", tr("A's point deepest inside B"), json_of(result_.point_a), "m"},
        {"b", "", tr("B's point deepest inside A, a − depth·n"), json_of(result_.point_b), "m"},
        {tr("SAT depth"), "", tr("the least overlap over the polygons' edge normals"), axis_.overlap, "m"},
        {tr("SAT axis"), "", fill(tr("the outward normal of that edge, {0}"), {axis_.edge}), json_of(axis_.normal),
         ""},
        {tr("EPA − SAT"), "", tr("the two depths' difference"), result_.depth - axis_.overlap, "m"},
        {tr("iterations"), "", tr("EPA's support points"), result_.iterations, ""},
        {tr("point"), "", tr("the narrow phase's deepest point (collide_convex, convex_contact.cpp)"),
         contact_ ? json_of(contact_->point) : Json(tr("none")), "m"},
        {tr("point depth"), "", tr("its depth: EPA's plus ρ_A + ρ_B = 0"),
         contact_ ? Json(contact_->depth) : Json(tr("none")), "m"}};
  }

  GjkResult overlap_;                 // GJK's result: an overlap, its last simplex a triangle
  std::vector<EpaIteration> record_;  // EPA's iterations, as epa() recorded them
  EpaResult result_;                  // EPA's normal n, depth and deepest points
  SeparatingAxis axis_;               // the separating axis test on the same pair
  std::optional<Collision> contact_;  // what the narrow phase returns for the pair
};

}  // namespace

tutorial::SceneFactory epa_scene() { return tutorial::scene<Epa>(); }

}  // namespace lamina::ch4
