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
    return point_name(figure().source(p)) + " to " + point_name(figure().source(q));
  }
  // EPA stops when s is no farther out than the edge (to 1e-10 max(1, d), gjk.cpp) or is a
  // point the polytope already has.
  std::string verdict(const EpaIteration& it) const {
    const bool held = std::any_of(it.polytope.begin(), it.polytope.end(),
                                  [&](const Vec2& p) { return (p - it.support).norm() <= 1e-12; });
    if (held) return "stop: s is a vertex already";
    if (gain(it) <= 1e-10 * std::max(1.0, it.distance)) return "stop: the edge is D's own";
    return "go on: s goes in";
  }

  void draw_start(render::Frame& frame) const override {
    frame.caption = "EPA · B moved into A: GJK's simplex is a triangle around O, the cores overlap";
    figure().draw_shapes(frame, nullptr, true);
    draw_simplex(frame, figure(), overlap_.simplex);
    frame.panels.push_back(
        panel("GJK on the overlapping pair: " + std::to_string(overlap_.iterations) + " iterations",
              {"its simplex " + names_of(overlap_.simplex),
               "holds O: the cores overlap, the distance is 0",
               "GJK cannot tell how deep: EPA grows this triangle",
               "to D's edge nearest O, whose distance is the depth"}));
    frame.legend = {{Sample::swatch, d_fill, "D = B − A"},
                    {Sample::point, kept, "GJK's last simplex"}};
  }

  void draw_iteration(render::Frame& frame, int k) const override {
    const EpaIteration& it = at(k);
    const auto [p, q] = edge_of(it);
    const SimplexVertex& s = figure().source(it.support);
    frame.caption =
        "EPA iteration " + std::to_string(k) +
        " · the polytope's edge nearest O, pushed out to D's support point along its normal";
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
              {"polytope: " + std::to_string(it.polytope.size()) + " points of D",
               "nearest edge " + edge_name(it),
               "its normal m = " + planar(it.normal) + ", distance " + fixed(it.distance, 4) + " m",
               "s = s_D(m) = " + point_name(s) + " = " + planar(it.support) + " m",
               "m·s − distance = " + fixed(gain(it), 4) + " m: " + verdict(it),
               "depth in [distance, m·s] = [" + fixed(it.distance, 4) + ", " +
                   fixed(it.normal.dot(it.support), 4) + "] m"}));
    frame.legend = {{Sample::swatch, d_fill, "D = B − A"},
                    {Sample::point, kept, "polytope"},
                    {Sample::line, nearest, "its edge nearest O"},
                    {Sample::arrow, palette::ink, "m: that edge's outward normal"},
                    {Sample::point, added, "s = s_D(m) = b_j − a_i"}};
  }

  void draw_answer(render::Frame& frame) const override {
    frame.caption = "EPA's answer · B moved by depth along n (dashed) only touches A";
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
    frame.labels.push_back({b + Vec2(0.35, -0.2), "depth·n", palette::ink, Align::right});
    const EpaIteration& it = at(iterations());
    figure().stroke(frame, it.polytope, kept, true, false);
    for (const Vec2& w : it.polytope) figure().mark(frame, w, kept, "");
    const auto [p, q] = edge_of(it);
    figure().stroke(frame, {p, q}, nearest, false, false);
    frame.arrows.push_back(
        {figure().at(Vec2::Zero()), figure().at(b - a), nearest, "b − a", std::nullopt});
    frame.panels.push_back(panel(
        "EPA ends after " + std::to_string(iterations()) + " iterations",
        {
            "depth = " + fixed(result_.depth, 4) + " m along n = −m = " + planar(result_.normal),
            "a = " + planar(a) + " m, A's point deepest in B",
            "b = a − depth·n = " + planar(b) + " m",
            "separating axes: least overlap " + fixed(axis_.overlap, 4) + " m, edge " + axis_.edge,
            "EPA − SAT = " + tutorial::scientific(result_.depth - axis_.overlap) + " m",
            "narrow phase: depth " + (contact_ ? fixed(contact_->depth, 4) + " m at b" : "none"),
        }));
    frame.legend = {{Sample::swatch, d_fill, "D = B − A"},
                    {Sample::point, kept, "the last polytope"},
                    {Sample::line, nearest, "D's edge nearest O"},
                    {Sample::arrow, nearest, "b − a = −depth·n"}};
  }

  tutorial::Section explain_start() const override {
    return {"GJK on the overlapping pair", triangle_quantities()};
  }

  std::vector<tutorial::Quantity> triangle_quantities() const {
    return {{"in words", "", "the step",
             "B overlaps A: after " + std::to_string(overlap_.iterations) +
                 " iterations GJK's simplex {" + names_of(overlap_.simplex) +
                 "} is a triangle holding O, so the cores overlap. Its "
                 "distance is 0; EPA starts from this triangle to find the depth.",
             ""},
            {"simplex", "", "GJK's last simplex, a triangle around O",
             rows_of(points_of(overlap_.simplex)), "m"},
            {"iterations", "", "GJK's support points", overlap_.iterations, ""}};
  }

  std::vector<tutorial::Quantity> iteration_quantities(int k) const override {
    const EpaIteration& it = at(k);
    return {
        {"in words", "", "the step",
         "Of the polytope's " + std::to_string(it.polytope.size()) +
             " edges the one nearest O runs " + edge_name(it) + ", at distance " +
             fixed(it.distance, 4) + " m along its outward normal m = " + planar(it.normal) +
             ". D's support point along m is s = " + point_name(figure().source(it.support)) +
             " = " + planar(it.support) + " m, " + fixed(gain(it), 4) +
             " m beyond the edge: " + verdict(it) + ".",
         ""},
        {"polytope", "", "D's points found so far, counter-clockwise", rows_of(it.polytope), "m"},
        {"m", "", "the nearest edge's outward unit normal", json_of(it.normal), ""},
        {"distance", "", "that edge's distance from O: a lower bound on the depth", it.distance,
         "m"},
        {"s", "", "s_D(m), D's point farthest along m", json_of(it.support), "m"},
        {"m·s", "", "an upper bound on the depth", it.normal.dot(it.support), "m"},
        {"m·s − distance", "", "how far s lies beyond the edge (stop at ≤ 1e-10 max(1, distance))",
         gain(it), "m"}};
  }

  std::vector<tutorial::Quantity> answer_quantities() const override {
    return {
        {"in words", "", "the result",
         "EPA's depth " + fixed(result_.depth, 4) + " m along n = " + planar(result_.normal) +
             "; the separating axis test's least overlap is " + fixed(axis_.overlap, 4) +
             " m (edge " + axis_.edge + "), " +
             tutorial::scientific(std::abs(result_.depth - axis_.overlap)) +
             " m apart. Moving B by depth·n leaves A and B touching.",
         ""},
        {"depth", "", "EPA: the distance of D's edge nearest O", result_.depth, "m"},
        {"n", "", "from A to B, minus that edge's outward normal", json_of(result_.normal), ""},
        {"a", "", "A's point deepest inside B", json_of(result_.point_a), "m"},
        {"b", "", "B's point deepest inside A, a − depth·n", json_of(result_.point_b), "m"},
        {"SAT depth", "", "the least overlap over the polygons' edge normals", axis_.overlap, "m"},
        {"SAT axis", "", "the outward normal of that edge, " + axis_.edge, json_of(axis_.normal),
         ""},
        {"EPA − SAT", "", "the two depths' difference", result_.depth - axis_.overlap, "m"},
        {"iterations", "", "EPA's support points", result_.iterations, ""},
        {"point", "", "the narrow phase's deepest point (collide_convex, convex_contact.cpp)",
         contact_ ? json_of(contact_->point) : Json("none"), "m"},
        {"point depth", "", "its depth: EPA's plus ρ_A + ρ_B = 0",
         contact_ ? Json(contact_->depth) : Json("none"), "m"}};
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
