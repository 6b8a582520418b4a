// Chapter 3 — constrained dynamics. Five scenes, each stepped by constrained_step:
//   incline            Fig 3-1: a box held on a line through p with normal N (eq. 3-1..3-4); the
//                      constraint force λN cancels the normal part of m g, and the box slides
//                      with g sin θ.
//   one_sided_incline  Fig 3-2, 3-3: the same line made one-sided, (x − p)·N ≥ 0 (eq. 3-17..3-22);
//                      the box thrown off it flies (λ = 0), lands and slides (λ > 0), and every
//                      step's (λ, W) is plotted on the text's sign diagram.
//   pendulum           a bob on a rod (distance constraint) twice: with β = 0 it drifts off the
//                      circle and |C| grows, β = 0.2 (eq. 3-14) pulls it back; pendulum_drift.png
//                      plots |C|.
//   chain              four links on revolute joints, pinned to the world, released straight at
//                      1.2 rad; each frame gives PGS's residual ‖W‖ (eq. 3-23, 3-24) from last
//                      step's λ and from zero, and pgs_residual.png plots ‖W‖ per sweep for both.
//   angle_limit        a bar on a pin stopped by an angle limit, the chapter's other inequality
//                      row, with its (λ, W) on the sign diagram.
// --explain STEP prints every row of that step: Jmap, Jsp, C, ζ, η, bounds, λ_exp, λ, W, the
// residual per sweep, the same step solved by the text's own PGS (its Jsp, Jmap, Bsp, a = B λ and
// λ after each sweep, beside the packed solver's λ), and the dense J, M⁻¹ and J M⁻¹ Jᵀ when small
// (ch3/constrained_system.h).
#include "ch3/angle_limit.h"
#include "ch3/chain.h"
#include "ch3/incline.h"
#include "ch3/one_sided_incline.h"
#include "ch3/pendulum.h"
#include "app/harness/tutorial.h"

int main(int argc, char** argv) {
  using namespace lamina;
  const tutorial::TutorialInfo info{
      "03_constraints",
      "ch3",
      "Chapter 3: Fig 3-1's incline, Fig 3-2/3-3's one-sided incline, a pendulum's drift, a chain "
      "with PGS's residual plot, and an angle limit",
      {render::Overlay::forces, render::Overlay::centres}};
  return tutorial::run_tutorial(argc, argv, info,
                                {ch3::incline_scene(), ch3::one_sided_incline_scene(),
                                 ch3::pendulum_scene(), ch3::chain_scene(), ch3::angle_limit_scene()});
}
