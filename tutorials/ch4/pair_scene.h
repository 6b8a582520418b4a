// What the GJK and EPA scenes (gjk_scene.h, epa_scene.h) share: one algorithm's run on the pair
// of pair_figure.h, a frame per moment of it. Frame 0 shows its start, frame k = 1..n its
// iteration k, frame n + 1 its answer; each draws D = B − A and says in the status line (top
// right) where the run is, "GJK · iteration 3 of 4", where a simulation's frames give t and the
// step (an algorithm's iterations are not time steps).
#pragma once

#include <string>
#include <vector>

#include "app/harness/tutorial.h"
#include "ch4/pair_figure.h"

namespace lamina::ch4 {

class PairScene : public tutorial::Scene {
 public:
  tutorial::SceneInfo info() const override;
  void step() override { ++frame_; }
  // D and the status line, then the start, iteration k or the answer over them.
  void draw(render::Frame& frame) const override;
  tutorial::Explanation explain() const override;

 protected:
  // `name`: the scene's, its frames' file prefix ("gjk"); `algorithm`: the run's, as its titles
  // name it ("GJK"); `figure`: the pair where the run sees it.
  PairScene(std::string name, std::string algorithm, PairFigure figure);

  const PairFigure& figure() const { return figure_; }
  // "GJK iteration 3 of 4": a panel's or an explanation's title.
  std::string iteration_title(int k) const;

 private:
  // n, the iterations the run took.
  virtual int iterations() const = 0;
  // What frame 0, frame k = 1..n and frame n + 1 draw over D.
  virtual void draw_start(render::Frame& frame) const = 0;
  virtual void draw_iteration(render::Frame& frame, int k) const = 0;
  virtual void draw_answer(render::Frame& frame) const = 0;
  // What they explain: the start under a title of its own, iteration k under "GJK iteration 3
  // of 4", the answer under "GJK's answer".
  virtual tutorial::Section explain_start() const = 0;
  virtual std::vector<tutorial::Quantity> iteration_quantities(int k) const = 0;
  virtual std::vector<tutorial::Quantity> answer_quantities() const = 0;

  int last() const { return iterations() + 1; }  // the answer's frame
  int shown() const;                              // the frame shown, 0..n + 1
  // Where frame k is in the run: "the start", "iteration 3 of 4", "the answer".
  std::string moment(int k) const;

  PairFigure figure_;      // the pair and D
  std::string name_;       // the scene's, e.g. "gjk"
  std::string algorithm_;  // the run's, e.g. "GJK"
  long frame_ = 0;         // steps taken: the frame shown, until the answer's
};

}  // namespace lamina::ch4
