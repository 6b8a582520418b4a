#include "app/views/contact/world_explanation.h"

#include "app/views/constraints/constraint_view.h"
#include "app/views/motion/body_view.h"
#include "language/language.h"

namespace lamina::view {
namespace {

using tutorial::Json;
using tutorial::json_of;

std::string pair_name(const std::vector<std::string>& names, const BodyPair& pair) {
  return names.at(static_cast<std::size_t>(pair.first)) + " – " +
         names.at(static_cast<std::size_t>(pair.second));
}

// What each row of the velocity MLCP stands for, read from the row map the step recorded.
std::vector<std::string> row_titles(const World& world, const WorldReport& report,
                                    const std::vector<std::string>& names) {
  std::vector<std::string> titles(static_cast<std::size_t>(report.velocity.mlcp.row_count()));
  // A friction row may serve both points of a pair (FrictionRows::per_manifold): its title
  // names every contact whose row it is.
  std::vector<std::string> friction_of(titles.size());
  std::vector<std::string> friction_pair(titles.size());
  std::vector<int> sharing(titles.size(), 0);
  int index = 0;
  for (const ContactPair& pair : report.pairs) {
    for (int k = 0; k < pair.count; ++k, ++index) {
      const Contact& c = pair.contacts[k];
      const std::string bodies = pair_name(names, pair.bodies);
      titles[c.row] =
          fill(tr("contact row of contact {0} ({1}) (eq. 4-3)"), {std::to_string(index), bodies});
      for (const int f : c.friction_rows) {
        if (f < 0) continue;
        const auto i = static_cast<std::size_t>(f);
        friction_of[i] = sharing[i]++ ? fill(tr("{0} and {1}"), {friction_of[i], std::to_string(index)})
                                      : std::to_string(index);
        friction_pair[i] = bodies;
      }
    }
  }
  for (const ContactPair& pair : report.pairs) {
    for (int k = 0; k < pair.count; ++k) {
      const Contact& c = pair.contacts[k];
      for (int axis = 0; axis < 2; ++axis) {
        const int f = c.friction_rows[static_cast<std::size_t>(axis)];
        if (f < 0) continue;
        const auto i = static_cast<std::size_t>(f);
        const char* pattern =
            sharing[i] > 1
                ? (axis == 0 ? tr("friction row of contacts {0} ({1}), one row at their middle, along u1 = z × n")
                             : tr("friction row of contacts {0} ({1}), one row at their middle, along u2 = z"))
                : (axis == 0 ? tr("friction row of contact {0} ({1}), along u1 = z × n")
                             : tr("friction row of contact {0} ({1}), along u2 = z"));
        titles[i] = fill(pattern, {friction_of[i], friction_pair[i]});
      }
    }
  }
  for (std::size_t j = 0; j < report.joints.size(); ++j) {
    const RowRange& rows = report.joints[j];
    for (int m = 0; m < rows.count; ++m) {
      titles[rows.first + m] = fill(tr("row {0} of {1} of joint {2} ({3})"),
                                    {std::to_string(m + 1), std::to_string(rows.count),
                                     std::to_string(j), world.joint(static_cast<int>(j)).kind()});
    }
  }
  return titles;
}

Section body_at_t(const std::string& name, const RigidBody& b, const Vec3& gravity) {
  Section s = body_section(fill(tr("{0} at t"), {name}), b, {"", "", "3-5", "3-5"});
  s.quantities.push_back({"m⁻¹", "5-1", tr("inverse mass"), b.inverse_mass, "1/kg"});
  s.quantities.push_back({"I⁻¹", "5-1, 2-8", tr("inverse inertia R I0⁻¹ Rᵀ"),
                          json_of(b.inverse_inertia_world), "1/(kg·m²)"});
  s.quantities.push_back({"F_ext", "5-2", "m g", json_of(Vec3(b.mass * gravity)), "N"});
  return s;
}

// A fixed body: the text's infinite mass, of which the step uses only the inverses (eq. 5-1).
Section fixed_body(const std::string& name, const RigidBody& b) {
  return {fill(tr("{0} (fixed)"), {name}),
          {{"x", "", tr("centre"), json_of(b.x), "m"},
           {"m", "5-1", tr("mass: infinite"), "∞", "kg"},
           {"m⁻¹", "5-1", tr("inverse mass"), b.inverse_mass, "1/kg"},
           {"I⁻¹", "5-1", tr("inverse inertia"), json_of(b.inverse_inertia_world), "1/(kg·m²)"}}};
}

Section contact_section(int index, const ContactPair& pair, const Contact& c,
                        const std::vector<std::string>& names, double dt) {
  const std::string origin =
      c.origin == ContactOrigin::fresh
          ? tr("new: this step's deepest point, no λ from before (Fig 4-2)")
      : c.origin == ContactOrigin::refound
          ? tr("re-found: this step's deepest point where a cached point was, warm-started from its λ")
      : pair.recycled
          ? tr("kept by the cache, its pair recycled (beyond the text): it barely moved since its "
               "points were found, so it was not collided again; re-placed from its anchors "
               "(eq. 5-12) and re-anchored")
          : tr("kept by the cache, re-placed from its anchors (eq. 5-12, Fig 4-4)");
  Json rows = Json::array({c.row});
  for (int r : c.friction_rows) {
    if (r >= 0) rows.push_back(r);
  }
  return {fill(tr("contact {0}: {1}, {2}"), {std::to_string(index), pair_name(names, pair.bodies), origin}),
          {{"c", "", tr("contact point, midway between the two surfaces"), json_of(lift(c.point)), "m"},
           {"n", "4-1",
            fill(tr("normal, from {0} into {1}"),
                 {names.at(static_cast<std::size_t>(pair.bodies.first)),
                  names.at(static_cast<std::size_t>(pair.bodies.second))}),
            json_of(lift(c.normal)), ""},
           {"C", "4-1", tr("separation (negative: penetrating)"), c.separation, "m"},
           {tr("rows"), "", tr("its contact row, then its friction rows"), rows, ""},
           {"λ_n", "4-3", tr("its contact row's λ"), c.lambda_normal, "N"},
           {"λ_n Δt", "", tr("the normal impulse over the step"), c.lambda_normal * dt, "N·s"},
           {"λ_t", "", tr("its friction row's λ along u1 = z × n"), c.lambda_tangent, "N"}}};
}

Section joint_section(const World& world, int j, const RowRange& rows,
                      const std::vector<std::string>& names) {
  const Constraint& joint = world.joint(j);
  const std::array<int, 2> bodies = joint.bodies();
  auto name = [&](int b) { return b < 0 ? std::string(tr("the world")) : names.at(static_cast<std::size_t>(b)); };
  return {fill(tr("joint {0}: {1} between {2} and {3}"),
               {std::to_string(j), joint.kind(), name(bodies[0]), name(bodies[1])}),
          {{tr("rows"), "", tr("its rows in the velocity MLCP"), Json::array({rows.first, rows.first + rows.count - 1}), ""}}};
}

}  // namespace

Explanation explain_world_step(const World& world, const WorldReport& report,
                               const std::vector<std::string>& names, bool each_row) {
  const std::vector<RigidBody>& at_t = report.bodies;
  const double dt = world.settings().step.dt;
  Explanation e;
  // each section tagged with the phase of World::step that computed it
  auto add = [&e](Section s, const char* phase) {
    s.phase = phase;
    e.push_back(std::move(s));
  };
  for (std::size_t i = 0; i < at_t.size(); ++i) {
    add(at_t[i].is_static() ? fixed_body(names.at(i), at_t[i])
                            : body_at_t(names.at(i), at_t[i], world.settings().step.gravity),
        "forces");
  }
  int index = 0;
  for (const ContactPair& pair : report.pairs) {
    for (int k = 0; k < pair.count; ++k) {
      // found by this step's collision detection (new, re-found) or kept by the cache
      add(contact_section(index++, pair, pair.contacts[k], names, dt),
          pair.contacts[k].origin == ContactOrigin::kept ? "cache" : "collision");
    }
  }
  for (std::size_t j = 0; j < report.joints.size(); ++j) {
    add(joint_section(world, static_cast<int>(j), report.joints[j], names), "rows");
  }
  const std::vector<std::string> titles = row_titles(world, report, names);
  for (int i = 0; each_row && i < report.velocity.mlcp.row_count(); ++i) {
    add(row_section(report.velocity, i, fill(tr("row {0}: {1}"), {std::to_string(i), titles[i]}), names), "rows");
  }
  if (report.velocity.mlcp.row_count() > 0) add(sweeps_section(report.velocity, tr("PGS (eq. 3-24)")), "solve");
  if (report.position.mlcp.row_count() > 0) {
    Section position = sweeps_section(report.position,
                                      tr("split impulse (beyond the text): the position MLCP's PGS"));
    position.quantities.push_back({"λ_p", "", tr("push-out λ of each contact row"),
                                   json_of(report.position.solution.lambda), "N"});
    add(position, "solve");
  }
  for (std::size_t i = 0; i < at_t.size(); ++i) {
    if (at_t[i].is_static()) continue;
    add({names.at(i) + ": F_c = Jᵀ λ", {constraint_force(report.velocity, static_cast<int>(i))}}, "Jᵀλ");
  }
  for (std::size_t i = 0; i < at_t.size(); ++i) {
    if (at_t[i].is_static()) continue;
    add(body_section(fill(tr("{0} at t + Δt"), {names.at(i)}), world.bodies()[i], {"2-5", "2-6", "2-3", "2-4"}),
        "integration");
  }
  if (std::optional<Section> dense = dense_section(report.velocity, at_t, tr("the dense system (small)"))) {
    add(*dense, "solve");
  }
  return e;
}

tutorial::ViewerStep viewer_step(const World& world, const WorldReport& report,
                                 const std::vector<std::string>& names) {
  tutorial::ViewerStep step;
  step.phases = explain_world_step(world, report, names, false);  // rows: the viewer's table
  step.body_names = names;
  const Vec3& g = world.settings().step.gravity;
  for (const RigidBody& body : report.bodies) step.at_t.push_back(viewer_body(body, g));
  for (const RigidBody& body : world.bodies()) step.after.push_back(viewer_body(body, g));
  add_viewer_rows(report.velocity, row_titles(world, report, names), step);
  step.method = world.settings().solver;
  const std::vector<ContactInfo> infos = report.contacts();  // in pair order, as below
  int index = 0;
  for (const ContactPair& pair : report.pairs) {
    for (int k = 0; k < pair.count; ++k, ++index) {
      const Contact& c = pair.contacts[k];
      const ContactInfo& info = infos.at(static_cast<std::size_t>(index));
      tutorial::ViewerContact view;
      view.bodies = {pair.bodies.first, pair.bodies.second};
      view.x = info.point.x();
      view.y = info.point.y();
      view.nx = info.normal.x();
      view.ny = info.normal.y();
      view.separation = info.separation;
      view.lambda_normal = info.lambda_normal;
      view.lambda_tangent = info.lambda_tangent;
      view.origin = origin_name(info.origin);
      view.row = c.row;
      step.rows.at(static_cast<std::size_t>(c.row)).kind = "contact";
      step.rows.at(static_cast<std::size_t>(c.row)).contact = index;
      for (const int f : c.friction_rows) {
        if (f >= 0) step.rows.at(static_cast<std::size_t>(f)).contact = index;
      }
      step.contacts.push_back(view);
    }
  }
  for (std::size_t j = 0; j < report.joints.size(); ++j) {
    const RowRange& rows = report.joints[j];
    const Constraint& constraint = world.joint(static_cast<int>(j));
    tutorial::ViewerJoint view;
    view.title = fill(tr("joint {0}: {1}"), {std::to_string(j), constraint.kind()});
    if (const std::optional<render::Joint> drawn = joint_view(report.bodies, constraint)) {
      view.x1 = drawn->a.x();
      view.y1 = drawn->a.y();
      view.x2 = drawn->b.x();
      view.y2 = drawn->b.y();
    }
    view.first_row = rows.first;
    view.row_count = rows.count;
    for (int m = 0; m < rows.count; ++m) {
      tutorial::ViewerRow& row = step.rows.at(static_cast<std::size_t>(rows.first + m));
      row.kind = "joint";
      row.joint = static_cast<int>(j);
    }
    step.joints.push_back(view);
  }
  return step;
}

}  // namespace lamina::view
