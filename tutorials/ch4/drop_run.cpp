#include "ch4/drop_run.h"

#include <algorithm>
#include <cmath>

#include "app/harness/format.h"
#include "app/views/contact/world_explanation.h"
#include "app/views/contact/world_view.h"
#include "language/language.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

namespace lamina::ch4 {
namespace {

using tutorial::fixed;

constexpr double force_scale = 0.1;     // the landing frames' arrow length per λ, in m per N
constexpr double longest_force = 16.0;  // forces above this (landing impacts) are drawn cut, in N
constexpr double squeeze = 0.1;         // N: friction at rest larger than this is a squeeze
constexpr double hover = 1e-4;          // m: a cached point this far above the ground hovers
const double g_magnitude = -StepSettings().gravity.y();  // |g|, in m/s²

// The bodies' names, in the language of the run (tr() at run time, not in an initialiser).
std::vector<std::string> drop_names() { return {tr("ground"), tr("box")}; }

// A contact's origin as the panel's column names it: "new", "refound", "kept" (origin_name),
// padded to one column of 7 (a Hangul syllable counted as two).
std::string origin_column(ContactOrigin origin) {
  std::string name = origin == ContactOrigin::fresh     ? tr("new")
                     : origin == ContactOrigin::refound ? tr("refound")
                                                        : tr("kept");
  std::size_t width = 0;
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x80) ++width;
    else if (u >= 0xE0) width += 2;  // the lead byte of a three-byte (Hangul) character
  }
  if (width < 7) name.append(7 - width, ' ');
  return name;
}

// Landing impacts are tens of times the weight: an arrow longer than `longest_force` is drawn
// at that length, and a label `offset` from its tip gives the force.
void cut_arrow(render::Frame& frame, const Vec2& from, const Vec2& direction, double& force,
               const std::string& symbol, render::Colour colour, const Vec2& offset) {
  if (std::abs(force) <= longest_force) return;
  const Vec2 tip = from + force_scale * std::copysign(longest_force, force) * direction;
  frame.labels.push_back({tip + offset, fill(tr("{0} = {1} N (arrow cut)"), {symbol, fixed(force, 0)}),
                          colour, render::Label::Align::left});
  force = std::copysign(longest_force, force);
}

// Roughly where a contact's corner is: the point lies midway between the corner and the ground's
// surface, so the corner is near c + (C/2) n (exactly for a fresh point).
Vec3 contact_corner(const ContactInfo& c) { return c.point + 0.5 * c.separation * c.normal; }

}  // namespace

World drop_world(const std::string& solver, bool cache) {
  Scene scene = builtin_scene("box-on-ground-tilted");
  scene.solver = solver;
  WorldSettings settings = world_settings(scene);
  settings.cache.enabled = cache;
  return build_world(scene, settings);
}

double penetration(const RigidBody& box) {
  const double angle = planar_angle(box.q);
  const double reach = 0.5 * std::abs(std::sin(angle)) + 0.5 * std::abs(std::cos(angle));
  return std::max(0.0, reach - box.x.y());
}

void draw_ground(render::Frame& frame) { frame.grounds.push_back({Vec2::Zero(), Vec2::UnitY()}); }

DropRun::DropRun(const std::string& solver, bool cache)
    : solver_(solver), cache_(cache), run_(drop_world(solver, cache)) {
  step();
}

void DropRun::step() {
  run_.step();
  moment_ = view::fig4_moment(run_.report(), 1, touched_);
  const std::vector<ContactInfo> contacts = run_.report().contacts();
  if (!touched_ && !contacts.empty()) first_corner_ = corner_side(contacts[0]);
  touched_ = touched_ || !contacts.empty();
}

const RigidBody& DropRun::box_at_t() const { return run_.bodies_at_t()[1]; }

// Which bottom corner of the box a contact is at, in the box's frame at t: −1 or +1.
double DropRun::corner_side(const ContactInfo& c) const {
  const RigidBody& box = box_at_t();
  return std::copysign(1.0, (box.rotation.transpose() * (contact_corner(c) - box.x)).x());
}

// "a" for the corner of the first contact, "b" for the other.
std::string DropRun::corner_name(const ContactInfo& c) const {
  return corner_side(c) == first_corner_ ? "a" : "b";
}

void DropRun::draw(render::Frame& frame, double dx, render::Colour colour) const {
  const Vec2 shift(dx, 0.0);
  frame.force_scale = force_scale;
  render::Body box = view::body_view(box_at_t(), run_.world().shape(1), tint(colour, 0.35));
  box.centre += shift;
  frame.bodies.push_back(box);
  for (const ContactInfo& c : run_.report().contacts()) {
    render::Contact view = view::contact_view(c);
    view.point += shift;
    cut_arrow(frame, view.point, view.normal, view.normal_force, "λ_n",
              render::palette::bluish_green, Vec2(0.08, 0.0));
    cut_arrow(frame, view.point, view.tangent, view.friction_force, "λ_t", render::palette::orange,
              Vec2(0.0, -0.3));
    frame.contacts.push_back(view);
    const bool left = corner_side(c) < 0.0;
    frame.labels.push_back({view.point + Vec2(left ? -0.14 : 0.14, 0.1), corner_name(c),
                            render::palette::ink,
                            left ? render::Label::Align::right : render::Label::Align::left});
  }
}

render::Panel DropRun::panel(render::Corner corner, render::Colour colour) const {
  const RigidBody& box = box_at_t();
  const std::vector<ContactInfo> contacts = run_.report().contacts();
  render::Panel p;
  p.corner = corner;
  p.title = fill(cache_ ? tr("solver {0} · cache on") : tr("solver {0} · cache off"), {solver_});
  p.title_colour = colour;
  p.lines = {"θ = " + fixed(planar_angle(box.q), 3) + " rad   ω = " +
                 fixed(box.angular_velocity.z(), 2) + " rad/s",
             fill(tr("penetration = {0} mm"), {fixed(1000.0 * penetration(box), 1)})};
  double total = 0.0, friction = 0.0;
  for (const ContactInfo& c : contacts) {
    const std::string origin = origin_column(c.origin);  // "new", "refound", "kept", in one column
    p.lines.push_back(corner_name(c) + " " + origin + " C = " +
                      fixed(c.separation, 4) + " m  λ_n = " + fixed(c.lambda_normal, 1) +
                      " N  λ_t = " + fixed(c.lambda_tangent, 1) + " N");
    total += c.lambda_normal;
    friction += c.lambda_tangent;
  }
  if (contacts.empty()) p.lines.push_back(tr("no contact: falling under m g"));
  p.lines.push_back("Σ λ_n = " + fixed(total, 2) + " N (m g = " + fixed(g_magnitude, 2) + " N), Σ λ_t = " +
                    fixed(friction, 2) + " N");
  // The text's method leaves two things Lamina's does not (contact/solvers.h): a kept point
  // above the ground that still pushes, and at rest friction squeezing the box.
  for (const ContactInfo& c : contacts) {
    if (c.cached && c.separation > hover && c.lambda_normal > 0.0) {
      p.lines.push_back(fill(tr("{0} pushes from {1} mm up: a kept gap asks ζ = 0 (eq. 4-4)"),
                             {corner_name(c), fixed(1000.0 * c.separation, 1)}));
    }
  }
  if (moment_ != view::Fig4Moment::at_rest) return p;
  if (contacts.size() == 2 && std::abs(contacts[0].lambda_tangent) > squeeze &&
      contacts[0].lambda_tangent * contacts[1].lambda_tangent < 0.0) {
    p.lines.push_back(fill(tr("λ_t = ±{0} N pull inwards: the two friction rows are"),
                           {fixed(std::abs(contacts[0].lambda_tangent), 1)}));
    p.lines.push_back(tr("one row twice, only their sum is fixed (pgs: one row)"));
  }
  return p;
}

std::string DropRun::moment() const {
  if (!cache_ && touched_ && moment_ != view::Fig4Moment::first_contact &&
      moment_ != view::Fig4Moment::no_contact) {
    return tr("cache off · only this step's deepest point: the box see-saws, never rests");
  }
  const std::vector<ContactInfo> contacts = run_.report().contacts();
  switch (moment_) {
    case view::Fig4Moment::no_contact:
      return touched_ ? tr("in the air: no contact") : tr("falling: no contact yet");
    case view::Fig4Moment::first_contact:
      return tr("Fig 4-2 · first contact: collision detection gives one new point, the deepest corner a");
    case view::Fig4Moment::one_point:
      for (const ContactInfo& c : contacts) {
        if (c.lambda_normal > 0.0) {
          return fill(tr("Fig 4-3 · one point pushes, corner {0}: the box turns over it"), {corner_name(c)});
        }
      }
      return fill(tr("Fig 4-3 · one point, pushing nothing this step: the box turns over corner {0}"),
                  {corner_name(contacts.front())});
    case view::Fig4Moment::two_points:
      for (const ContactInfo& fresh : contacts) {
        for (const ContactInfo& kept : contacts) {
          if (fresh.origin == ContactOrigin::fresh && kept.origin == ContactOrigin::kept) {
            return fill(tr("Fig 4-4 · corner {0} goes in, new, while {1} is kept by the cache: both push, solved together"),
                        {corner_name(fresh), corner_name(kept)});
          }
        }
      }
      return tr("Fig 4-4 · both corners push, solved together");
    case view::Fig4Moment::at_rest:
      return tr("Fig 4-5 · at rest on two points, kept or re-found, together carrying m g");
  }
  return "";
}

tutorial::Explanation DropRun::explain() const {
  return view::explain_world_step(run_.world(), run_.report(), drop_names());
}

tutorial::ViewerStep DropRun::viewer_step() const {
  return view::viewer_step(run_.world(), run_.report(), drop_names());
}

}  // namespace lamina::ch4
