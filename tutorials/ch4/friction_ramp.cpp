#include "ch4/friction_ramp.h"

#include <array>
#include <cmath>

#include "app/harness/format.h"
#include "app/views/contact/stepped_world.h"
#include "app/views/contact/world_explanation.h"
#include "app/views/contact/world_view.h"
#include "contact/solvers.h"
#include "language/language.h"

namespace lamina::ch4 {
namespace {

using tutorial::fixed;

const double dt = StepSettings().dt;           // Δt, in s (the World's default)
const double g = -StepSettings().gravity.y();  // |g|, in m/s²

// A box on a ramp of angle θ: it sticks when tan θ < μ and slides at g (sin θ − μ cos θ) else.
struct Ramp {
  double theta;          // θ, in rad
  Vec3 centre;           // the ramp's centre, in m
  render::Colour colour;
  render::Corner corner;  // where its panel goes
};

class FrictionRamp : public tutorial::Scene {
 public:
  static constexpr double mu = 0.5;          // μ of both materials, so the pair's √(μ1 μ2) = 0.5
  static constexpr double half_length = 2.6; // ramp half length, in m
  static constexpr double half_thickness = 0.15;
  static constexpr double start = 1.6;       // the box's start up the slope from the centre, in m
  inline static const Vec2 box_half{0.35, 0.25};

  explicit FrictionRamp(const tutorial::Options& o)
      : world_(ramps_world(o.solver.value_or("pgs"), !o.no_cache)) {
    world_.step();
  }

  tutorial::SceneInfo info() const override {
    return {"friction_ramp", dt, 90, 1, {Vec2(-6.4, -2.3), Vec2(6.4, 3.2)}};
  }
  void step() override { world_.step(); }

  void draw(render::Frame& frame) const override {
    frame.caption = fill(tr("Friction, bounds ±μ λc: sticks when tan θ < μ, slides when tan θ > μ · solver {0}"),
                         {world_.world().settings().solver});
    frame.force_scale = 0.35;
    for (std::size_t i = 0; i < ramps_.size(); ++i) {
      const int ramp = static_cast<int>(2 * i), box = ramp + 1;
      frame.bodies.push_back(body(ramp, render::palette::grid));
      frame.bodies.push_back(body(box, tint(ramps_[i].colour, 0.35)));
      frame.panels.push_back(panel(i));
    }
    for (const ContactInfo& c : world_.report().contacts()) {
      frame.contacts.push_back(view::contact_view(c));
    }
    frame.legend_corner = render::Corner::top_left;
  }

  tutorial::Explanation explain() const override {
    return view::explain_world_step(world_.world(), world_.report(),
                                    {fill(tr("ramp {0}"), {"20°"}), fill(tr("box on {0}"), {"20°"}),
                                     fill(tr("ramp {0}"), {"35°"}), fill(tr("box on {0}"), {"35°"})});
  }

 private:
  inline static const std::array<Ramp, 2> ramps_{
      Ramp{20.0 * M_PI / 180.0, Vec3(-3.4, 0.6, 0.0), render::palette::bluish_green,
           render::Corner::bottom_left},
      Ramp{35.0 * M_PI / 180.0, Vec3(3.4, 0.8, 0.0), render::palette::vermillion,
           render::Corner::bottom_right}};

  // Each ramp (a static box, body 2i) with a box on it (body 2i + 1), released at rest.
  static World ramps_world(const std::string& solver, bool cache) {
    WorldSettings settings = with_solver(WorldSettings(), solver);
    settings.cache.enabled = cache;
    World world(settings);
    const Material material{mu, 0.0};
    for (const Ramp& r : ramps_) {
      world.add_static_box(half_length, half_thickness, r.centre, r.theta, material);
      const Vec3 up_slope(std::cos(r.theta), std::sin(r.theta), 0.0);
      const Vec3 normal(-std::sin(r.theta), std::cos(r.theta), 0.0);
      world.add_box(1.0, box_half.x(), box_half.y(),
                    r.centre + start * up_slope + (half_thickness + box_half.y()) * normal, r.theta,
                    material);
    }
    return world;
  }

  render::Body body(int i, render::Colour fill) const {
    return view::body_view(world_.bodies_at_t()[static_cast<std::size_t>(i)], world_.world().shape(i), fill);
  }

  render::Panel panel(std::size_t i) const {
    const Ramp& r = ramps_[i];
    const int box = static_cast<int>(2 * i + 1);
    const Vec3 down_slope(-std::cos(r.theta), -std::sin(r.theta), 0.0);
    const RigidBody& at_t = world_.bodies_at_t()[static_cast<std::size_t>(box)];
    const RigidBody& after = world_.world().bodies()[static_cast<std::size_t>(box)];
    const double measured = (after.v - at_t.v).dot(down_slope) / dt;
    // Coulomb sliding (not in the text, which has no ramp): m a = m g sin θ − μ m g cos θ.
    const double predicted = g * (std::sin(r.theta) - mu * std::cos(r.theta));
    double normal = 0.0, friction = 0.0;
    for (const ContactInfo& c : world_.report().contacts()) {
      if (c.bodies.second != box) continue;
      normal += c.lambda_normal;
      friction += c.lambda_tangent;
    }
    const bool slides = std::tan(r.theta) > mu;
    render::Panel p;
    p.corner = r.corner;
    p.title = fill(slides ? tr("θ = {0}°: tan θ = {1} > μ = {2}, slides")
                          : tr("θ = {0}°: tan θ = {1} < μ = {2}, sticks"),
                   {fixed(r.theta * 180.0 / M_PI, 0), fixed(std::tan(r.theta), 3), fixed(mu, 1)});
    p.title_colour = r.colour;
    p.lines = {"g (sin θ − μ cos θ) = " + fixed(predicted, 3) + " m/s²" +
                   (slides ? "" : tr(" < 0: friction holds")),
               fill(tr("a along the slope = {0} m/s² (solved)"), {fixed(measured, 3)}),
               fill(tr("v along the slope = {0} m/s"), {fixed(after.v.dot(down_slope), 3)}),
               "|Σ λ_t| = " + fixed(std::abs(friction), 3) + " N,  μ Σ λ_n = " +
                   fixed(mu * normal, 3) + " N"};
    return p;
  }

  view::SteppedWorld world_;
};

}  // namespace

tutorial::SceneFactory friction_ramp_scene() {
  return [](const tutorial::Options& o) { return std::make_unique<FrictionRamp>(o); };
}

}  // namespace lamina::ch4
