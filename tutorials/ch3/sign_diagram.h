// Fig 3-3: the sign region of an inequality row (eq. 3-20..3-22), drawn in a rectangle of a
// frame, with the (λ, W) pair that every step of a run solved plotted on it.
//
//   W = (J B λ − η)_i = (J V(t+Δt) − ζ)_i / Δt   (eq. 3-23; the text's αλ + β of eq. 3-20 for C = 0)
//   λ ≥ 0,  W ≥ 0,  λ W = 0                        (eq. 3-21, 3-22)
// The allowed pairs are the two half-axes, hatched as the text hatches them: λ = 0 with W ≥ 0
// (the row does not push: the body leaves, or keeps away from, C = 0) and W = 0 with λ > 0
// (it pushes just enough that C does not pass 0). The rest of the plane is forbidden: λ < 0
// would pull, W < 0 would cross, and λ > 0 with W > 0 would push a body that is leaving.
#pragma once

#include <string>
#include <vector>

#include "kinematics/math_types.h"
#include "render/frame.h"

namespace lamina::ch3 {

class SignDiagram {
 public:
  struct Axis {
    double full;       // the value at the end of the axis (λ in N or N·m; W in m/s² or rad/s²)
    double tick;       // the step between labelled ticks, in the same unit
    std::string name;  // "λ (N)", "W (m/s²)"
  };

  enum class Caption { above, below };  // where the diagram's caption goes

  // A diagram with its origin (λ = 0, W = 0) at `origin` and axes `size` long (the frame's
  // metres), scaled to λ ∈ [0, lambda.full] and W ∈ [0, W.full] (the negative sides are drawn a
  // quarter as long). `row` names the inequality row in the caption.
  SignDiagram(const Vec2& origin, const Vec2& size, Axis lambda, Axis W, std::string row,
              Caption caption);

  // Adds step k's pair: λ_i and W_i as the step solved them.
  void record(double lambda, double W);
  // Draws the axes, the allowed half-axes hatched, the forbidden regions named, and the pairs
  // recorded so far, the last (step k's) marked.
  void draw(render::Frame& frame) const;

 private:
  Vec2 at(double lambda, double W) const;  // a pair's place in the frame, in m

  Vec2 origin_;            // where (0, 0) is drawn, in m
  Vec2 size_;              // the lengths of the λ and W axes, in m
  Axis lambda_, W_;        // the two axes' scales and names
  std::string row_;        // the row the pairs belong to
  Caption caption_;        // above the W axis, or below the λ axis
  std::vector<Vec2> pairs_;  // (λ, W) of every step so far
};

}  // namespace lamina::ch3
