// Chapter 4's tilted landing (the built-in scene box-on-ground-tilted: the ground, body 0, and a
// 1 kg unit box dropped from y = 2 m tilted by 0.3 rad, body 1, μ = 0.6), one run of it with a
// solver and the cache on or off, and what the story of Fig 4-2..4-5 has seen so far. It shows
// step k: the state at t = k Δt with what step k solved from it.
#pragma once

#include <string>
#include <vector>

#include "app/harness/explanation.h"
#include "app/harness/viewer.h"
#include "app/views/contact/contact_story.h"
#include "app/views/contact/stepped_world.h"
#include "render/frame.h"

namespace lamina::ch4 {

// The landing's World under `solver` (contact/solvers.h), with the contact cache on or off.
World drop_world(const std::string& solver, bool cache);

// How deep the box's lowest corner is below the ground's top y = 0, in m (0 when above).
double penetration(const RigidBody& box);

// The ground's surface, y = 0, drawn as a half-plane.
void draw_ground(render::Frame& frame);

class DropRun {
 public:
  DropRun(const std::string& solver, bool cache);

  // Takes the next step.
  void step();

  // Draws the box, its contacts with their forces, and corner names, shifted by `dx` in x.
  void draw(render::Frame& frame, double dx, render::Colour colour) const;
  // The run's numbers: solver and cache, pose, spin, each contact with its C and λ, their sums,
  // and at rest what the text's method leaves that Lamina's does not.
  render::Panel panel(render::Corner corner, render::Colour colour) const;
  // The moment of Fig 4-2..4-5 the step is at, in the figures' words.
  std::string moment() const;
  view::Fig4Moment fig4() const { return moment_; }
  // What step k solved (views/contact/world_explanation.h).
  tutorial::Explanation explain() const;
  // The same step for the step-through viewer.
  tutorial::ViewerStep viewer_step() const;

  const std::string& solver() const { return solver_; }
  bool cache() const { return cache_; }

 private:
  const RigidBody& box_at_t() const;
  double corner_side(const ContactInfo& c) const;
  std::string corner_name(const ContactInfo& c) const;

  std::string solver_;
  bool cache_;
  view::SteppedWorld run_;
  view::Fig4Moment moment_ = view::Fig4Moment::no_contact;  // of the step shown
  bool touched_ = false;       // a step before it had a contact
  double first_corner_ = 0.0;  // side (−1, +1) of corner a, the first contact's
};

}  // namespace lamina::ch4
