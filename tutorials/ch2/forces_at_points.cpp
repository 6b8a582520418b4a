#include "ch2/forces_at_points.h"

#include <array>

#include "app/harness/format.h"
#include "app/harness/sketch3d.h"
#include "app/views/motion/body_view.h"
#include "kinematics/particle.h"
#include "kinematics/wrench.h"
#include "language/language.h"
#include "motion/integrator.h"

namespace lamina::ch2 {
namespace {

using tutorial::fixed;
using tutorial::json_of;

constexpr double frame_dt = 1.0 / 30.0;  // Δt, in s
const Vec2 half_extents(1.0, 0.6);       // the body, a box, in m
constexpr double plate_density = 1.0;    // kg/m²: m = 2.4 kg
constexpr double force_scale = 0.5;      // m of arrow per N
constexpr double torque_scale = 1.0;     // m of arrow per N·m (along z, drawn obliquely)

// A force fixed in direction, applied at a point fixed in the body.
struct AppliedForce {
  const char* name;  // its subscript, "₀", "₁" or "₂": F₀ is applied at x₀
  Vec3 offset;       // r_i(0): the point in the body frame, from the centre of mass, in m
  Vec3 force;        // F_i, in N, world frame
};

const std::array<AppliedForce, 3> applied{{{"₀", Vec3(-1.0, 0.3, 0.0), Vec3(-1.2, -0.4, 0.0)},
                                           {"₁", Vec3(-0.3, 0.6, 0.0), Vec3(-0.5, 1.4, 0.0)},
                                           {"₂", Vec3(1.0, -0.3, 0.0), Vec3(1.8, 0.2, 0.0)}}};

// x_i = x + R r_i(0) (eq. 1-25): where the force is applied now.
Vec3 point_of(const RigidBody& body, const AppliedForce& f) {
  return particle_position(body.x, body.rotation, f.offset);
}

// τ_i = (x_i − x) × F_i (eq. 1-32): the torque of one force, as a wrench of that force alone.
Vec3 torque_of(const RigidBody& body, const AppliedForce& f) {
  Wrench one;
  one.add_at_point(f.force, point_of(body, f), body.x);
  return one.torque;
}

class ForcesAtPoints : public tutorial::Scene {
 public:
  ForcesAtPoints() : body_(box_body(plate_density, half_extents.x(), half_extents.y(), Vec3::Zero())) {
    step();  // step 0: a frame shows the body at t with the forces its step applies
  }

  tutorial::SceneInfo info() const override {
    return {"forces_at_points", frame_dt, 46, 1, {Vec2(-5.95, -1.4), Vec2(2.3, 2.9)}};
  }

  // Takes the next step: the forces at their points add up in the body's accumulators
  // (eq. 1-31, 1-33), then eq. 2-3..2-8 move it. No gravity: only the three forces act.
  void step() override {
    at_t_ = body_;
    for (const AppliedForce& f : applied) at_t_.apply_force_at(f.force, point_of(at_t_, f));
    body_ = at_t_;
    integrate(body_, frame_dt);
    body_.clear_forces();
    trail_.push_back(at_t_.x.head<2>());
  }

  void draw(render::Frame& frame) const override {
    using namespace render::palette;
    frame.caption =
        tr("Ch 2 · Fig 2-1: forces at points add up to F = ΣFᵢ, τ = Σ(xᵢ − x) × Fᵢ "
           "(eq. 1-31..1-33)");
    frame.paths.push_back({trail_, grey, false});
    frame.bodies.push_back(view::box_view(at_t_, half_extents, tint(sky_blue, 0.35)));
    const Vec3& x = at_t_.x;
    for (const AppliedForce& f : applied) {
      const Vec3 p = point_of(at_t_, f);
      frame.paths3.push_back({{x, p}, grey, true});
      frame.arrows3.push_back(
          {p, p + force_scale * f.force, vermillion, std::string("F") + f.name});
      frame.points3.push_back({p, ink, ""});
      // xᵢ's name inside the body, beside the point and off its lever arm
      const Vec3 inward = (x - p).normalized(), across = Vec3::UnitZ().cross(inward);
      frame.labels3.push_back({p + 0.22 * inward + 0.12 * across, std::string("x") + f.name, ink,
                               render::Label::Align::centre});
    }
    frame.arrows3.push_back({x, x + force_scale * at_t_.force, bluish_green, "F = ΣFᵢ"});
    frame.arrows3.push_back({x, x + torque_scale * at_t_.torque, reddish_purple, "τ"});
    frame.legend = {
        {render::LegendEntry::Sample::arrow, vermillion, tr("Fᵢ applied at xᵢ")},
        {render::LegendEntry::Sample::dashed_line, grey, tr("lever arm xᵢ − x")},
        {render::LegendEntry::Sample::arrow, bluish_green, tr("F = ΣFᵢ (1-31), drawn at x")},
        {render::LegendEntry::Sample::arrow, reddish_purple,
         tr("τ = Σ(xᵢ − x) × Fᵢ (1-33), along z")},
        {render::LegendEntry::Sample::line, grey, tr("path of x")}};
    tutorial::draw_world_axes(frame, Vec3(1.45, -1.0, 0.0), 0.5);
    frame.legend_corner = render::Corner::bottom_left;
    frame.panels.push_back(numbers_panel());
  }

  tutorial::Explanation explain() const override {
    tutorial::Explanation e;
    for (const AppliedForce& f : applied) {
      const std::string i = f.name;
      e.push_back({fill(tr("Force {0}"), {f.name}),
                   {{"x" + i, "1-25", tr("x + R rᵢ(0), where it is applied"),
                     json_of(point_of(at_t_, f)), "m"},
                    {"F" + i, "", tr("the force"), json_of(f.force), "N"},
                    {"τ" + i, "1-32", "(xᵢ − x) × Fᵢ", json_of(torque_of(at_t_, f)), "N·m"}}});
    }
    e.push_back({tr("The body"),
                 {{"x(t)", "", tr("centre of mass at t"), json_of(at_t_.x), "m"},
                  {"F", "1-31", "Σ Fᵢ", json_of(at_t_.force), "N"},
                  {"τ", "1-33", "Σ (xᵢ − x) × Fᵢ", json_of(at_t_.torque), "N·m"},
                  {"v(t+Δt)", "2-3", "v + m⁻¹ F Δt", json_of(body_.v), "m/s"},
                  {"ω(t+Δt)", "2-4", "ω + I⁻¹ τ Δt", json_of(body_.angular_velocity), "rad/s"},
                  {"x(t+Δt)", "2-5", "x + v(t+Δt) Δt", json_of(body_.x), "m"}}});
    return e;
  }

 private:
  render::Panel numbers_panel() const {
    render::Panel panel;
    panel.corner = render::Corner::top_left;
    panel.title = fill(tr("The forces in numbers (m = {0} kg)"), {fixed(at_t_.mass, 1)});
    for (const AppliedForce& f : applied) {
      const std::string i = f.name;
      panel.lines.push_back(
          fill(tr("F{0} = {1} N at x{0} − x = {2} m"),
               {i, fixed(f.force, 2), fixed(Vec3(point_of(at_t_, f) - at_t_.x), 2)}));
      panel.lines.push_back("   (x" + i + " − x) × F" + i + " = " + fixed(torque_of(at_t_, f), 2) +
                            " N·m  (1-32)");
    }
    panel.lines.push_back("F = ΣFᵢ = " + fixed(at_t_.force, 2) + " N  (1-31)");
    panel.lines.push_back("τ = Σ(xᵢ − x) × Fᵢ = " + fixed(at_t_.torque, 2) + " N·m  (1-33)");
    panel.lines.push_back(fill(tr("v = {0} m/s, then v + m⁻¹F Δt  (2-3)"), {fixed(at_t_.v, 2)}));
    panel.lines.push_back(fill(tr("ω = {0} rad/s, then ω + I⁻¹τ Δt  (2-4)"),
                               {fixed(at_t_.angular_velocity, 2)}));
    panel.lines.push_back(fill(tr("arrows: {0} m per N, {1} m per N·m"),
                               {fixed(force_scale, 1), fixed(torque_scale, 1)}));
    return panel;
  }

  RigidBody body_;           // after the last step: at t + Δt
  RigidBody at_t_;           // at t, with the forces of its step accumulated (F, τ)
  std::vector<Vec2> trail_;  // the centre's path up to t
};

}  // namespace

tutorial::SceneFactory forces_at_points_scene() { return tutorial::scene<ForcesAtPoints>(); }

}  // namespace lamina::ch2
