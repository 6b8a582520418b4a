#include "app/views/contact/world_explanation.h"

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
      const std::string bodies = " (" + pair_name(names, pair.bodies) + ")";
      titles[c.row] = "contact row of contact " + std::to_string(index) + bodies + " (eq. 4-3)";
      for (const int f : c.friction_rows) {
        if (f < 0) continue;
        const auto i = static_cast<std::size_t>(f);
        friction_of[i] += (sharing[i]++ ? " and " : "") + std::to_string(index);
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
        titles[i] = std::string("friction row of ") + (sharing[i] > 1 ? "contacts " : "contact ") +
                    friction_of[i] + friction_pair[i] + (sharing[i] > 1 ? ", one row at their middle" : "") +
                    (axis == 0 ? ", along u1 = z × n" : ", along u2 = z");
      }
    }
  }
  for (std::size_t j = 0; j < report.joints.size(); ++j) {
    const RowRange& rows = report.joints[j];
    for (int m = 0; m < rows.count; ++m) {
      titles[rows.first + m] = "row " + std::to_string(m + 1) + " of " +
                               std::to_string(rows.count) + " of joint " + std::to_string(j) + " (" +
                               world.joint(static_cast<int>(j)).kind() + ")";
    }
  }
  return titles;
}

Section body_at_t(const std::string& name, const RigidBody& b, const Vec3& gravity) {
  Section s = body_section(name + " at t", b, {"", "", "3-5", "3-5"});
  s.quantities.push_back({"m⁻¹", "5-1", "inverse mass", b.inverse_mass, "1/kg"});
  s.quantities.push_back({"I⁻¹", "5-1, 2-8", "inverse inertia R I0⁻¹ Rᵀ",
                          json_of(b.inverse_inertia_world), "1/(kg·m²)"});
  s.quantities.push_back({"F_ext", "5-2", "m g", json_of(Vec3(b.mass * gravity)), "N"});
  return s;
}

// A fixed body: the text's infinite mass, of which the step uses only the inverses (eq. 5-1).
Section fixed_body(const std::string& name, const RigidBody& b) {
  return {name + " (fixed)",
          {{"x", "", "centre", json_of(b.x), "m"},
           {"m", "5-1", "mass: infinite", "∞", "kg"},
           {"m⁻¹", "5-1", "inverse mass", b.inverse_mass, "1/kg"},
           {"I⁻¹", "5-1", "inverse inertia", json_of(b.inverse_inertia_world), "1/(kg·m²)"}}};
}

Section contact_section(int index, const ContactPair& pair, const Contact& c,
                        const std::vector<std::string>& names, double dt) {
  const std::string origin =
      c.origin == ContactOrigin::fresh
          ? "new: this step's deepest point, no λ from before (Fig 4-2)"
      : c.origin == ContactOrigin::refound
          ? "re-found: this step's deepest point where a cached point was, warm-started from its λ"
          : "kept by the cache, re-placed from its anchors (eq. 5-12, Fig 4-4)";
  Json rows = Json::array({c.row});
  for (int r : c.friction_rows) {
    if (r >= 0) rows.push_back(r);
  }
  return {"contact " + std::to_string(index) + ": " + pair_name(names, pair.bodies) + ", " + origin,
          {{"c", "", "contact point, midway between the two surfaces", json_of(lift(c.point)), "m"},
           {"n", "4-1", "normal, from " + names.at(static_cast<std::size_t>(pair.bodies.first)) +
                            " into " + names.at(static_cast<std::size_t>(pair.bodies.second)),
            json_of(lift(c.normal)), ""},
           {"C", "4-1", "separation (negative: penetrating)", c.separation, "m"},
           {"rows", "", "its contact row, then its friction rows", rows, ""},
           {"λ_n", "4-3", "its contact row's λ", c.lambda_normal, "N"},
           {"λ_n Δt", "", "the normal impulse over the step", c.lambda_normal * dt, "N·s"},
           {"λ_t", "", "its friction row's λ along u1 = z × n", c.lambda_tangent, "N"}}};
}

Section joint_section(const World& world, int j, const RowRange& rows,
                      const std::vector<std::string>& names) {
  const Constraint& joint = world.joint(j);
  const std::array<int, 2> bodies = joint.bodies();
  auto name = [&](int b) { return b < 0 ? std::string("the world") : names.at(static_cast<std::size_t>(b)); };
  return {"joint " + std::to_string(j) + ": " + joint.kind() + " between " + name(bodies[0]) +
              " and " + name(bodies[1]),
          {{"rows", "", "its rows in the velocity MLCP", Json::array({rows.first, rows.first + rows.count - 1}), ""}}};
}

}  // namespace

Explanation explain_world_step(const World& world, const WorldReport& report,
                               const std::vector<std::string>& names) {
  const std::vector<RigidBody>& at_t = report.bodies;
  const double dt = world.settings().step.dt;
  Explanation e;
  for (std::size_t i = 0; i < at_t.size(); ++i) {
    e.push_back(at_t[i].is_static() ? fixed_body(names.at(i), at_t[i])
                                    : body_at_t(names.at(i), at_t[i], world.settings().step.gravity));
  }
  int index = 0;
  for (const ContactPair& pair : report.pairs) {
    for (int k = 0; k < pair.count; ++k) e.push_back(contact_section(index++, pair, pair.contacts[k], names, dt));
  }
  for (std::size_t j = 0; j < report.joints.size(); ++j) {
    e.push_back(joint_section(world, static_cast<int>(j), report.joints[j], names));
  }
  const std::vector<std::string> titles = row_titles(world, report, names);
  for (int i = 0; i < report.velocity.mlcp.row_count(); ++i) {
    e.push_back(row_section(report.velocity, i, "row " + std::to_string(i) + ": " + titles[i], names));
  }
  if (report.velocity.mlcp.row_count() > 0) e.push_back(sweeps_section(report.velocity, "PGS (eq. 3-24)"));
  if (report.position.mlcp.row_count() > 0) {
    Section position = sweeps_section(report.position,
                                      "split impulse (beyond the text): the position MLCP's PGS");
    position.quantities.push_back({"λ_p", "", "push-out λ of each contact row",
                                   json_of(report.position.solution.lambda), "N"});
    e.push_back(position);
  }
  for (std::size_t i = 0; i < at_t.size(); ++i) {
    if (at_t[i].is_static()) continue;
    Section after = body_section(names.at(i) + " at t + Δt", world.bodies()[i], {"2-5", "2-6", "2-3", "2-4"});
    after.quantities.insert(after.quantities.begin(), constraint_force(report.velocity, static_cast<int>(i)));
    e.push_back(after);
  }
  if (std::optional<Section> dense = dense_section(report.velocity, at_t, "the dense system (small)")) {
    e.push_back(*dense);
  }
  return e;
}

}  // namespace lamina::view
