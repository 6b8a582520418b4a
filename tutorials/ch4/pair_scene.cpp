#include "ch4/pair_scene.h"

#include <algorithm>
#include <utility>

#include "constraints/step_settings.h"
#include "language/language.h"

namespace lamina::ch4 {
namespace {

const double pair_dt = StepSettings().dt;  // Δt, in s: the pair is what one step's narrow phase sees
const render::Rect view{Vec2(-4.6, -2.35), Vec2(5.3, 2.75)};  // both scenes' world region, in m

}  // namespace

PairScene::PairScene(std::string name, std::string algorithm, PairFigure figure)
    : figure_(std::move(figure)), name_(std::move(name)), algorithm_(std::move(algorithm)) {}

tutorial::SceneInfo PairScene::info() const { return {name_, pair_dt, last() + 1, 1, view}; }

void PairScene::draw(render::Frame& frame) const {
  figure_.draw_difference(frame);
  frame.legend_corner = render::Corner::bottom_right;
  const int k = shown();
  frame.status = algorithm_ + " · " + moment(k);
  if (k == 0) return draw_start(frame);
  if (k == last()) return draw_answer(frame);
  draw_iteration(frame, k);
}

tutorial::Explanation PairScene::explain() const {
  const int k = shown();
  if (k == 0) return {explain_start()};
  if (k == last()) return {{fill(tr("{0}'s answer"), {algorithm_}), answer_quantities()}};
  return {{iteration_title(k), iteration_quantities(k)}};
}

std::string PairScene::iteration_title(int k) const { return algorithm_ + " " + moment(k); }

int PairScene::shown() const { return static_cast<int>(std::min<long>(frame_, last())); }

std::string PairScene::moment(int k) const {
  if (k == 0) return tr("the start");
  if (k == last()) return tr("the answer");
  return fill(tr("iteration {0} of {1}"), {std::to_string(k), std::to_string(iterations())});
}

}  // namespace lamina::ch4
