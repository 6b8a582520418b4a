#include "ch4/contact_geometry.h"

#include <cmath>
#include <limits>
#include <optional>

#include "app/harness/format.h"
#include "app/views/contact/stepped_world.h"
#include "app/views/contact/world_explanation.h"
#include "app/views/contact/world_view.h"
#include "contact/solvers.h"
#include "kinematics/rotation.h"
#include "language/language.h"

namespace lamina::ch4 {
namespace {

using tutorial::fixed;

const double world_dt = StepSettings().dt;  // Δt, in s (the World's default)

// "(x, y)": the scene is planar, the z components are 0.
std::string xy_of(const Vec3& v) { return "(" + fixed(v.x(), 3) + ", " + fixed(v.y(), 3) + ")"; }

class ContactGeometry : public tutorial::Scene {
 public:
  inline static const Vec3 support_centre{-0.4, 0.5, 0.0};  // x1, in m
  inline static const Vec2 support_half{1.4, 0.5};          // body 1's half extents, in m
  static constexpr double tilt = 0.45;                       // body 2's angle, in rad
  static constexpr double start_depth = 0.002;               // its lowest corner's depth at t = 0, in m
  static constexpr double corner_x = 0.5;                    // and that corner's x, in m
  static constexpr double normal_length = 0.5;               // n1's arrow, in m
  static constexpr double normal_offset = 0.45;              // and its foot's distance from p1, in m

  explicit ContactGeometry(const tutorial::Options& o)
      : world_(two_boxes(o.solver.value_or("text"), !o.no_cache)) {
    world_.step();
  }

  tutorial::SceneInfo info() const override {
    return {"contact_geometry", world_dt, 30, 1, {Vec2(-2.6, -0.3), Vec2(3.0, 2.7)}};
  }
  void step() override { world_.step(); }

  void draw(render::Frame& frame) const override {
    frame.caption = fill(tr("Fig 4-1 · one contact: C = (x2 + r2 − x1 − r1)·n1 (eq. 4-1) · solver {0}"),
                         {world_.world().settings().solver});
    for (int i = 0; i < 2; ++i) {
      render::Body body = view::body_view(world_.bodies_at_t()[static_cast<std::size_t>(i)],
                                          world_.world().shape(i),
                                          i == 0 ? render::palette::grid
                                                 : tint(render::palette::sky_blue, 0.35));
      body.fixed = false;  // mark body 1's centre x1 too
      frame.bodies.push_back(body);
    }
    for (const ContactInfo& c : world_.report().contacts()) {
      frame.contacts.push_back(view::contact_view(c));
    }
    frame.legend_corner = render::Corner::bottom_right;
    const std::optional<ContactInfo> shown = shown_contact();
    if (!shown) return;
    const Geometry geo = geometry(*shown);
    const Vec2 x1 = geo.x1.head<2>(), x2 = geo.x2.head<2>(), p1 = geo.p1.head<2>(),
               p2 = geo.p2.head<2>(), n1 = geo.n1.head<2>();
    frame.arrows.push_back({x1, p1, render::palette::vermillion, "", std::nullopt});
    frame.arrows.push_back({x2, p2, render::palette::blue, "", std::nullopt});
    // n1 is the normal of body 1's whole face: drawn beside p1, clear of the force arrows.
    const Vec2 foot = p1 - normal_offset * Vec2(n1.y(), -n1.x());
    frame.arrows.push_back({foot, foot + normal_length * n1, render::palette::ink, "", std::nullopt});
    frame.labels.push_back({foot + 0.5 * normal_length * n1 + Vec2(-0.06, 0.0), "n1",
                            render::palette::ink, render::Label::Align::right});
    frame.labels.push_back({0.5 * (x1 + p1) + Vec2(0.05, -0.14), "r1", render::palette::vermillion,
                            render::Label::Align::left});
    frame.labels.push_back({0.5 * (x2 + p2) + Vec2(-0.08, 0.0), "r2", render::palette::blue,
                            render::Label::Align::right});
    frame.labels.push_back({x1 + Vec2(0.0, -0.2), "x1", render::palette::ink,
                            render::Label::Align::centre});
    frame.labels.push_back({x2 + Vec2(0.1, 0.06), "x2", render::palette::ink,
                            render::Label::Align::left});
    frame.labels.push_back({p1 + Vec2(0.12, -0.14), "p1 ≈ p2", render::palette::ink,
                            render::Label::Align::left});
    frame.panels.push_back(panel(*shown, geo));
  }

  tutorial::Explanation explain() const override {
    return view::explain_world_step(world_.world(), world_.report(), {fill(tr("body {0}"), {"1"}), fill(tr("body {0}"), {"2"})});
  }

 private:
  // The text's names for one contact: each body's centre, its surface point and the lever to it.
  struct Geometry {
    Vec3 x1, x2;  // the centres of mass, in m
    Vec3 p1, p2;  // the two surface points, p1 on body 1 and p2 (the corner) on body 2, in m
    Vec3 r1, r2;  // r1 = p1 − x1, r2 = p2 − x2, in m
    Vec3 n1;      // body 1's outward normal at p1, unit
  };

  // The text's geometry from the bodies' poses alone, not from the engine's contact: p2 is body
  // 2's corner nearest the contact, p1 its foot on body 1's face with normal n1 (body 1 is not
  // rotated, so that face lies |n1x| hx + |n1y| hy from x1 along n1).
  Geometry geometry(const ContactInfo& c) const {
    const RigidBody& body1 = world_.bodies_at_t()[0];
    const RigidBody& body2 = world_.bodies_at_t()[1];
    Geometry geo;
    geo.x1 = body1.x;
    geo.x2 = body2.x;
    geo.n1 = c.normal;
    double nearest = std::numeric_limits<double>::infinity();
    for (const double sx : {-0.5, 0.5}) {
      for (const double sy : {-0.5, 0.5}) {
        const Vec3 corner = body2.x + body2.rotation * Vec3(sx, sy, 0.0);
        if ((corner - c.point).norm() < nearest) {
          nearest = (corner - c.point).norm();
          geo.p2 = corner;
        }
      }
    }
    const double face = std::abs(geo.n1.x()) * support_half.x() + std::abs(geo.n1.y()) * support_half.y();
    geo.p1 = geo.p2 - ((geo.p2 - geo.x1).dot(geo.n1) - face) * geo.n1;
    geo.r1 = geo.p1 - geo.x1;
    geo.r2 = geo.p2 - geo.x2;
    return geo;
  }

  // The point this step's narrow phase returned (the deepest) if there is one, else the first
  // point the cache kept.
  std::optional<ContactInfo> shown_contact() const {
    const std::vector<ContactInfo> contacts = world_.report().contacts();
    for (const ContactInfo& c : contacts) {
      if (!c.cached) return c;
    }
    if (contacts.empty()) return std::nullopt;
    return contacts.front();
  }

  render::Panel panel(const ContactInfo& c, const Geometry& geo) const {
    const double separation = (geo.x2 + geo.r2 - geo.x1 - geo.r1).dot(geo.n1);
    render::Panel p;
    p.corner = render::Corner::top_left;
    p.title = fill(c.cached ? tr("a point kept by the cache at t = {0} s") : tr("the deepest point at t = {0} s"),
                   {fixed(world_.report().time, 3)});
    p.lines = {"x1 = " + xy_of(geo.x1) + "   x2 = " + xy_of(geo.x2) + " m",
               "r1 = " + xy_of(geo.r1) + "   r2 = " + xy_of(geo.r2) + " m",
               fill(tr("n1 = {0}, body 1's outward normal"), {xy_of(geo.n1)}),
               fill(tr("(x2 + r2 − x1 − r1)·n1 = {0} mm (eq. 4-1)"), {fixed(1000.0 * separation, 2)}),
               fill(c.separation < 0.0 ? tr("the engine's C = {0} mm: < 0, the corner is in")
                                       : tr("the engine's C = {0} mm: ≥ 0, apart"),
                    {fixed(1000.0 * c.separation, 2)}),
               fill(tr("λ = {0} N pushes along n1 on body 2 (eq. 4-3)"), {fixed(c.lambda_normal, 2)})};
    return p;
  }

  // Body 1: a fixed 2.8 × 1 m box; body 2: a 1 kg unit box, tilted, its lowest corner
  // start_depth into body 1's top face at x = corner_x.
  static World two_boxes(const std::string& solver, bool cache) {
    WorldSettings settings = with_solver(WorldSettings(), solver);
    settings.cache.enabled = cache;
    World world(settings);
    world.add_static_box(support_half.x(), support_half.y(), support_centre);
    const Vec3 lowest_corner = rotation_z(tilt) * Vec3(-0.5, -0.5, 0.0);
    const double top = support_centre.y() + support_half.y();
    world.add_box(1.0, 0.5, 0.5, Vec3(corner_x, top - start_depth, 0.0) - lowest_corner, tilt);
    return world;
  }

  view::SteppedWorld world_;
};

}  // namespace

tutorial::SceneFactory contact_geometry_scene() {
  return [](const tutorial::Options& o) { return std::make_unique<ContactGeometry>(o); };
}

}  // namespace lamina::ch4
