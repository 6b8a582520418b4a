#include "ch4/gjk_scene.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "app/harness/format.h"
#include "ch4/pair_figure.h"
#include "ch4/pair_scene.h"
#include "contact/gjk.h"
#include "language/language.h"

namespace lamina::ch4 {
namespace {

namespace palette = render::palette;
using Align = render::Label::Align;
using Sample = render::LegendEntry::Sample;
using tutorial::fixed;

const Vec2 b_apart(-1.1, 1.0);     // B's centroid, in m
const Vec2 gjk_origin(1.1, 0.55);  // where O is drawn: D right of the shapes, above the legend

constexpr double arrow_gap = 0.15;    // the −w arrow stops this far short of O, in m
constexpr double label_offset = 0.2;  // an arrow's name this far beside its middle, in m

// GJK on the pair apart: the start, one frame per iteration, the answer.
class Gjk : public PairScene {
 public:
  Gjk()
      : PairScene("gjk", "GJK", PairFigure(b_apart, gjk_origin, -1.0)),
        result_(gjk(figure().a(), figure().b(), &record_)) {}

 private:
  int iterations() const override { return static_cast<int>(record_.size()); }

  // The simplex iteration k started from, before its reduction: the one before it and the
  // point that iteration added (the first iteration: b₀ − a₀).
  Simplex unreduced(int k) const {
    if (k == 1) return Simplex{{record_[0].simplex.points[0]}, 1};
    Simplex s = record_[static_cast<std::size_t>(k - 2)].simplex;
    s.points[static_cast<std::size_t>(s.count++)] =
        record_[static_cast<std::size_t>(k - 2)].support;
    return s;
  }

  // w · w − w · s: how much nearer the origin s can bring the simplex; GJK stops at
  // ≤ 1e-10 |w|² (gjk.cpp) or when s is a point the simplex already had.
  static double progress(const GjkIteration& it) {
    return it.closest.squaredNorm() - it.closest.dot(it.support.w);
  }
  bool repeats(int k) const {
    const Simplex s = unreduced(k);
    const SimplexVertex& v = record_[static_cast<std::size_t>(k - 1)].support;
    return std::any_of(s.points.begin(), s.points.begin() + s.count, [&](const SimplexVertex& p) {
      return p.index_a == v.index_a && p.index_b == v.index_b;
    });
  }
  // "The simplex {…} is cut to {…}" or "… keeps its points".
  std::string reduction(int k) const {
    const Simplex before = unreduced(k), after = record_[static_cast<std::size_t>(k - 1)].simplex;
    if (before.count == after.count)
      return fill(tr("The simplex {{0}} keeps its points"), {names_of(after)});
    return fill(tr("The simplex {{0}} is cut to {{1}}"), {names_of(before), names_of(after)});
  }
  std::string verdict(int k) const {
    const GjkIteration& it = record_[static_cast<std::size_t>(k - 1)];
    if (repeats(k)) return tr("stop: s was in the simplex");
    if (progress(it) <= 1e-10 * it.closest.squaredNorm()) return tr("stop: s is no nearer");
    return tr("go on: s joins the simplex");
  }

  void draw_start(render::Frame& frame) const override {
    const SimplexVertex& w0 = record_[0].simplex.points[0];
    frame.caption =
        tr("GJK · the shapes are apart iff O ∉ D = B − A; their distance is min |w| over D");
    figure().draw_shapes(frame, &w0, true);
    figure().mark(frame, w0.w, kept, "w = " + point_name(w0));
    frame.panels.push_back(panel(
        tr("GJK on a hexagon A and a triangle B"),
        {tr("A: a₀..a₅, B: b₀..b₂ (world frame)"),
         fill(tr("D = hull of the {0} points b_j − a_i: {1} vertices"),
              {std::to_string(figure().difference_count()),
               std::to_string(figure().difference().size())}),
         tr("each iteration asks D for s_D(d) = s_B(d) − s_A(−d):"),
         tr("B's vertex farthest along d minus A's along −d"),
         fill(tr("start: w = b₀ − a₀ = {0} m"), {planar(w0.w)})}));
    frame.legend = {{Sample::swatch, d_fill, tr("D = B − A (Minkowski difference)")},
                    {Sample::point, kept, tr("GJK's simplex: points of D")},
                    {Sample::arrow, added, tr("b_j − a_i: a point of D")}};
  }

  void draw_iteration(render::Frame& frame, int k) const override {
    const GjkIteration& it = record_[static_cast<std::size_t>(k - 1)];
    const Simplex before = unreduced(k);
    frame.caption = fill(tr("GJK iteration {0} · the simplex's point w nearest O, then D's support point along −w"),
                         {std::to_string(k)});
    figure().draw_shapes(frame, &it.support, true);
    if (before.count > it.simplex.count)
      figure().stroke(frame, points_of(before), palette::grey, true, true);
    for (int i = 0; i < before.count; ++i) {  // the points the reduction dropped, named
      const SimplexVertex& v = before.points[static_cast<std::size_t>(i)];
      const bool dropped =
          std::none_of(it.simplex.points.begin(), it.simplex.points.begin() + it.simplex.count,
                       [&](const SimplexVertex& p) { return p.w == v.w; });
      if (dropped) figure().mark(frame, v.w, palette::grey, fill(tr("{0} dropped"), {point_name(v)}));
    }
    draw_simplex(frame, figure(), it.simplex);
    figure().mark(frame, it.closest, nearest, "w");
    const double w = it.closest.norm();
    const Vec2 tip = (arrow_gap / w) * it.closest;
    frame.arrows.push_back(
        {figure().at(it.closest), figure().at(tip), palette::ink, "", std::nullopt});
    const Vec2 middle = 0.5 * (it.closest + tip), side = tangent_of(it.closest / w);
    frame.labels.push_back(
        {figure().at(middle + label_offset * side), "−w", palette::ink, Align::centre});
    figure().mark(frame, it.support.w, added, "s");
    const double lower = it.closest.dot(it.support.w) / w;  // w·s/|w| ≤ the distance
    frame.panels.push_back(panel(
        iteration_title(k),
        {before.count > it.simplex.count
             ? fill(tr("simplex {0} (cut from {1})"),
                    {names_of(it.simplex), std::to_string(before.count)})
             : fill(tr("simplex {0}"), {names_of(it.simplex)}),
         "w = " + planar(it.closest) + " m, |w| = " + fixed(w, 4) + " m",
         "d = −w/|w| = " + planar(it.direction),
         "s = s_D(d) = " + point_name(it.support) + " = " + planar(it.support.w) + " m",
         "w·w − w·s = " + fixed(progress(it), 4) + " m²: " + verdict(k),
         fill(tr("distance in [w·s/|w|, |w|] = [{0}, {1}] m"),
              {fixed(std::max(0.0, lower), 4), fixed(w, 4)})}));
    frame.legend = {{Sample::swatch, d_fill, "D = B − A"},
                    {Sample::point, kept, tr("simplex")},
                    {Sample::point, nearest, tr("w: its point nearest O")},
                    {Sample::arrow, palette::ink, tr("−w: the search direction")},
                    {Sample::point, added, tr("s = s_D(−w) = b_j − a_i, added")}};
    if (before.count > it.simplex.count) {
      frame.legend.insert(frame.legend.begin() + 2,
                          {Sample::dashed_line, palette::grey, tr("before the reduction")});
    }
  }

  void draw_answer(render::Frame& frame) const override {
    frame.caption = tr("GJK's answer · the distance |w| and the closest points a, b (w = b − a)");
    figure().draw_shapes(frame, nullptr, false);
    const Vec2 a = result_.point_a, b = result_.point_b;
    frame.paths3.push_back({{lift(a), lift(b)}, palette::ink, true});
    frame.points3.push_back({lift(a), nearest, ""});
    frame.points3.push_back({lift(b), nearest, ""});
    frame.labels.push_back({a + Vec2(-0.12, 0.0), "a", nearest, Align::right});
    frame.labels.push_back({b + Vec2(0.12, 0.0), "b", nearest, Align::left});
    frame.labels.push_back({0.5 * (a + b) + Vec2(0.0, -0.3), fixed(result_.distance, 4) + " m",
                            palette::ink, Align::centre});
    draw_simplex(frame, figure(), result_.simplex);
    const Vec2 w = b - a;
    frame.arrows.push_back({figure().at(Vec2::Zero()), figure().at(w), nearest, "w", std::nullopt});
    frame.panels.push_back(
        panel(fill(tr("GJK ends after {0} iterations"), {std::to_string(iterations())}),
              {
                  fill(tr("iteration {0}: {1}"), {std::to_string(iterations()), verdict(iterations())}),
                  fill(tr("distance = |w| = {0} m"), {fixed(result_.distance, 4)}),
                  fill(tr("a = {0} m on {1}"), {planar(a), feature(0)}),
                  fill(tr("b = {0} m on {1}"), {planar(b), feature(1)}),
                  "n = (b − a)/|b − a| = " + planar(result_.normal),
                  fill(tr("narrow phase: {0} m > ρ_A + ρ_B = 0: apart"), {fixed(result_.distance, 4)}),
              }));
    frame.legend = {{Sample::swatch, d_fill, "D = B − A"},
                    {Sample::point, kept, tr("the last simplex")},
                    {Sample::arrow, nearest, tr("w = b − a, D's point nearest O")}};
  }

  // The feature of A (0) or B (1) its closest point lies on: a vertex, or an edge when the last
  // simplex's points come from two of its vertices.
  std::string feature(int body) const {
    const Simplex& s = result_.simplex;
    std::vector<int> indices;
    for (int i = 0; i < s.count; ++i) {
      const int index = body == 0 ? s.points[i].index_a : s.points[i].index_b;
      if (std::find(indices.begin(), indices.end(), index) == indices.end())
        indices.push_back(index);
    }
    const char name = body == 0 ? 'a' : 'b';
    if (indices.size() == 1)
      return fill(tr("{0}'s vertex {1}"), {body == 0 ? "A" : "B", vertex_name(name, indices[0])});
    return fill(tr("{0}'s edge {1}"), {body == 0 ? "A" : "B",
                                       vertex_name(name, indices[0]) + vertex_name(name, indices[1])});
  }

  tutorial::Section explain_start() const override {
    return {tr("GJK: A and B apart, and D = B − A"), start_quantities()};
  }

  std::vector<tutorial::Quantity> start_quantities() const {
    const SimplexVertex& w0 = record_[0].simplex.points[0];
    std::vector<Vec2> a(figure().a().vertices.begin(),
                        figure().a().vertices.begin() + figure().a().count);
    std::vector<Vec2> b(figure().b().vertices.begin(),
                        figure().b().vertices.begin() + figure().b().count);
    return {
        {tr("in words"), "", tr("the step"),
         fill(tr("D = B − A is the hull of the {0} differences b_j − a_i; A and B are apart iff O is "
                 "outside D, and their distance is D's least |w|. GJK starts from w = b₀ − a₀ = {1} m."),
              {std::to_string(figure().difference_count()), planar(w0.w)}),
         ""},
        {"a_i", "", tr("A's vertices (a hexagon), world frame"), rows_of(a), "m"},
        {"b_j", "", tr("B's vertices (a triangle), world frame"), rows_of(b), "m"},
        {"D", "", tr("the vertices of D = B − A, counter-clockwise"), rows_of(figure().difference()),
         "m"},
        {"w", "", tr("GJK's first point, b₀ − a₀"), json_of(w0.w), "m"}};
  }

  std::vector<tutorial::Quantity> iteration_quantities(int k) const override {
    const GjkIteration& it = record_[static_cast<std::size_t>(k - 1)];
    const double w = it.closest.norm();
    return {
        {tr("in words"), "", tr("the step"),
         fill(tr("{0}, whose point nearest O is w = {1} m (|w| = {2} m). Along d = −w/|w| D's support "
                 "point is s = {3} = {4} m; w·w − w·s = {5} m²: {6}."),
              {reduction(k), planar(it.closest), fixed(w, 4), point_name(it.support),
               planar(it.support.w), fixed(progress(it), 4), verdict(k)}),
         ""},
        {tr("simplex"), "", tr("its points after the reduction"), rows_of(points_of(it.simplex)), "m"},
        {"w", "", tr("the simplex's point nearest O"), json_of(it.closest), "m"},
        {"|w|", "", tr("an upper bound on the distance"), w, "m"},
        {"d", "", tr("the search direction −w/|w|"), json_of(it.direction), ""},
        {"s_A(−d)", "", fill(tr("A's vertex farthest along −d, {0}"), {vertex_name('a', it.support.index_a)}),
         json_of(it.support.a), "m"},
        {"s_B(d)", "", fill(tr("B's vertex farthest along d, {0}"), {vertex_name('b', it.support.index_b)}),
         json_of(it.support.b), "m"},
        {"s", "", tr("s_D(d) = s_B(d) − s_A(−d), the point added"), json_of(it.support.w), "m"},
        {"w·w − w·s", "", tr("how much nearer s brings the simplex (stop at ≤ 1e-10 |w|²)"),
         progress(it), "m²"},
        {"w·s/|w|", "", tr("a lower bound on the distance"), it.closest.dot(it.support.w) / w, "m"}};
  }

  std::vector<tutorial::Quantity> answer_quantities() const override {
    return {{tr("in words"), "", tr("the result"),
             fill(tr("After {0} iterations ({1}) the distance is {2} m between a on {3} and b on {4}."),
                  {std::to_string(iterations()), verdict(iterations()), fixed(result_.distance, 4),
                   feature(0), feature(1)}),
             ""},
            {tr("distance"), "", "|w| = |b − a|", result_.distance, "m"},
            {"a", "", tr("A's point nearest B"), json_of(result_.point_a), "m"},
            {"b", "", tr("B's point nearest A"), json_of(result_.point_b), "m"},
            {"n", "", tr("(b − a)/|b − a|, from A to B"), json_of(result_.normal), ""},
            {tr("iterations"), "", tr("support points asked for"), result_.iterations, ""}};
  }

  std::vector<GjkIteration> record_;  // GJK's iterations, as gjk() recorded them
  GjkResult result_;                  // GJK's distance and closest points
};

}  // namespace

tutorial::SceneFactory gjk_scene() { return tutorial::scene<Gjk>(); }

}  // namespace lamina::ch4
