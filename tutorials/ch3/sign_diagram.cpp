#include "ch3/sign_diagram.h"

#include <algorithm>
#include <utility>

#include "app/harness/format.h"
#include "language/language.h"

namespace lamina::ch3 {
namespace {

namespace palette = render::palette;
using Align = render::Label::Align;

constexpr double negative_part = 0.25;  // the negative half-axes, as a fraction of the positive
constexpr double past_end = 1.05;       // where a pair beyond an axis's scale is drawn

// A small disc at `at`: a plotted pair.
render::Body dot(const Vec2& at, double radius, render::Colour colour) {
  render::Body d;
  d.shape = render::Body::Shape::circle;
  d.centre = at;
  d.radius = radius;
  d.fill = colour;
  d.fixed = true;
  return d;
}

}  // namespace

SignDiagram::SignDiagram(const Vec2& origin, const Vec2& size, Axis lambda, Axis W, std::string row,
                         Caption caption)
    : origin_(origin),
      size_(size),
      lambda_(std::move(lambda)),
      W_(std::move(W)),
      row_(std::move(row)),
      caption_(caption) {}

void SignDiagram::record(double lambda, double W) { pairs_.emplace_back(lambda, W); }

Vec2 SignDiagram::at(double lambda, double W) const {
  // a pair past an axis's end is drawn just past it (the scenes choose ranges that hold a run)
  const double x = std::min(lambda / lambda_.full, past_end), y = std::min(W / W_.full, past_end);
  return origin_ + Vec2(x * size_.x(), y * size_.y());
}

void SignDiagram::draw(render::Frame& frame) const {
  const Vec2 ex(size_.x(), 0.0), ey(0.0, size_.y());
  const double unit = 0.02 * std::min(size_.x(), size_.y());  // hatch and tick size, in m
  const double caption_height = caption_ == Caption::above ? 1.32 : -0.45;
  frame.labels.push_back({origin_ + caption_height * ey - negative_part * ex,
                          fill(tr("Fig 3-3 · (λ, W) of the {0} (eq. 3-21)"), {row_}), palette::ink,
                          Align::left});
  // the axes, each from its negative part to past the end of its scale
  for (const auto& [axis, name] : {std::pair{ex, lambda_.name}, std::pair{ey, W_.name}}) {
    frame.arrows.push_back({origin_ - negative_part * axis, origin_ + 1.1 * axis, palette::ink, name, std::nullopt});
  }
  // eq. 3-21: the allowed pairs are the two half-axes, hatched
  for (const Vec2& axis : {ex, ey}) {
    frame.paths.push_back({{origin_, origin_ + axis}, palette::bluish_green, false});
    const Vec2 slant = (axis.normalized() + Vec2(-axis.y(), axis.x()).normalized()) * unit;
    for (double s = 0.0; s <= 1.0 + 1e-9; s += 0.04) {
      const Vec2 p = origin_ + s * axis;
      frame.paths.push_back({{p - slant, p + slant}, palette::bluish_green, false});
    }
  }
  // ticks with their values: λ's below its axis, W's left of its axis
  for (double v = lambda_.tick; v <= lambda_.full + 1e-9; v += lambda_.tick) {
    const Vec2 p = at(v, 0.0), down(0.0, unit);
    frame.paths.push_back({{p - 2.0 * down, p - 3.5 * down}, palette::ink, false});
    frame.labels.push_back({p - 5.5 * down, tutorial::fixed(v, 0), palette::grey, Align::centre});
  }
  for (double v = W_.tick; v <= W_.full + 1e-9; v += W_.tick) {
    const Vec2 p = at(0.0, v), left(unit, 0.0);
    frame.paths.push_back({{p - 2.0 * left, p - 3.5 * left}, palette::ink, false});
    frame.labels.push_back({p - 4.5 * left, tutorial::fixed(v, 0), palette::grey, Align::right});
  }
  // the allowed half-axes and the forbidden regions, named
  frame.labels.push_back(
      {origin_ + 0.04 * ex + 0.92 * ey, tr("λ = 0: free"), palette::blue, Align::left});
  frame.labels.push_back(
      {origin_ + 0.97 * ex + 0.08 * ey, tr("W = 0: on C = 0"), palette::vermillion, Align::right});
  frame.labels.push_back({origin_ + 0.55 * ex + 0.5 * ey, tr("λ > 0 and W > 0: λ W ≠ 0"),
                          palette::grey, Align::centre});
  frame.labels.push_back(
      {origin_ + 0.55 * ex - 0.24 * ey, tr("W < 0: C would pass 0"), palette::grey, Align::centre});
  frame.labels.push_back(
      {origin_ - 0.03 * ex - 0.24 * ey, tr("λ < 0: a pull"), palette::grey, Align::right});
  // the pairs up to step k: free (λ = 0) blue, pushing (λ > 0) vermillion, step k's larger
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const Vec2& pair = pairs_[k];
    const bool last = k + 1 == pairs_.size();
    const render::Colour colour = last ? palette::reddish_purple : pair.x() > 0.0 ? palette::vermillion : palette::blue;
    frame.bodies.push_back(dot(at(pair.x(), pair.y()), (last ? 1.6 : 0.9) * unit, colour));
  }
}

}  // namespace lamina::ch3
