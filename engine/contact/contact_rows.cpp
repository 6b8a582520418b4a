#include "contact/contact_rows.h"

#include <algorithm>
#include <array>
#include <utility>

#include "constraints/mlcp.h"

namespace lamina {
namespace {

// The levers of a contact point c: r = c − x for each body of the pair that moves, in Jmap's
// order. A static body never moves (eq. 5-1), so it enters as the world and the rows keep only
// the other body's block, as eq. 5-8 writes it.
struct Levers {
  int count = 0;                    // the moving bodies, 1 or 2
  std::array<int, 2> body{-1, -1};  // their indices
  std::array<double, 2> sign{};     // −1 for body 1, +1 for body 2 (the signs of eq. 4-3)
  std::array<Vec3, 2> r;            // r = c − x, in m
};

Levers levers_at(const std::vector<RigidBody>& bodies, const BodyPair& pair, const Vec2& c) {
  Levers levers;
  for (const auto& [body, sign] : {std::pair{pair.first, -1.0}, std::pair{pair.second, 1.0}}) {
    if (bodies[body].is_static()) continue;
    levers.body[levers.count] = body;
    levers.sign[levers.count] = sign;
    levers.r[levers.count++] = lift(c) - bodies[body].x;
  }
  return levers;
}

// A row as ConstraintRow's defaults make it: new rows are copied from it, which costs less than
// value-initialising each one in place.
const ConstraintRow blank_row;

// Appends the row of direction u at the levers' contact point.
ConstraintRow& append_row(std::vector<ConstraintRow>& rows, const Levers& levers, const Vec3& u) {
  ConstraintRow& row = rows.emplace_back(blank_row);
  for (int k = 0; k < levers.count; ++k) {
    // eq. 4-3: J = [−uᵀ  −(r1×u)ᵀ  uᵀ  (r2×u)ᵀ], r1 = c − x1, r2 = c − x2
    row.Jsp[k].head<3>() = levers.sign[k] * u;
    row.Jsp[k].tail<3>() = levers.sign[k] * levers.r[k].cross(u);
    row.Jmap[k] = levers.body[k];
  }
  return row;
}

// The velocity a cached point with a gap may approach at.
double gap_velocity(double separation, double dt) {
  // notes fix 6: a gap C > 0 may close within the step, no faster: J V ≥ −C/Δt (0 when touching)
  return separation > 0.0 ? -separation / dt : 0.0;
}

// The velocity that pushes a penetration out, a slop deep being left alone.
double push_out_velocity(double separation, const ContactSettings& settings, double dt) {
  // eq. 4-4, 4-5: J V ≥ ζ/Δt, ζ = −β min(C, 0); here with C + slop
  return -settings.beta * std::min(separation + settings.slop, 0.0) / dt;
}

void append_contact_row(std::vector<ConstraintRow>& rows, const ContactPair& pair,
                        const Contact& contact, const Levers& levers,
                        const std::vector<RigidBody>& bodies, const ContactSettings& settings,
                        double dt) {
  ConstraintRow& row = append_row(rows, levers, lift(contact.normal));
  // eq. 4-3, 5-10: 0 ≤ λ < ∞
  row.lambda_min = 0.0;
  row.zeta = gap_velocity(contact.separation, dt);
  if (settings.correction == PositionCorrection::baumgarte) {
    row.zeta += push_out_velocity(contact.separation, settings, dt);
  }
  // Restitution (beyond the text): a touching point approaching faster than v_e leaves at e times
  // its approach speed J V(t). With e = 0 that asks for ζ ≥ 0, which ζ already is when touching.
  if (pair.restitution == 0.0 || contact.separation > 0.0) return;
  const double approach = row_velocity(row, bodies);
  if (approach < -settings.restitution_threshold) {
    row.zeta = std::max(row.zeta, -pair.restitution * approach);
  }
}

void append_friction_row(std::vector<ConstraintRow>& rows, const ContactPair& pair,
                         const Levers& levers, const Vec3& u, int contact_row_index) {
  ConstraintRow& row = append_row(rows, levers, u);
  // eq. 3-26 with λ± = ±μ λc, λc read from the contact row during the iterations
  row.friction_of = contact_row_index;
  row.mu = pair.friction;
}

}  // namespace

int friction_rows_per_contact(const ContactPair& pair, const ContactSettings& settings) {
  if (pair.friction == 0.0) return 0;
  return settings.out_of_plane_friction ? 2 : 1;
}

double row_velocity(const ConstraintRow& row, const std::vector<RigidBody>& bodies) {
  double jv = row.Jsp[0].dot(velocity_of(bodies[row.Jmap[0]]));
  if (!row.is_one_body()) jv += row.Jsp[1].dot(velocity_of(bodies[row.Jmap[1]]));
  return jv;
}

void add_contact_rows(const std::vector<ContactPair>& pairs, const std::vector<RigidBody>& bodies,
                      const ContactSettings& settings, double dt, std::vector<ConstraintRow>& rows,
                      std::vector<double>& warm_start, std::vector<RowKind>& kinds) {
  for (const ContactPair& pair : pairs) {
    const int first = static_cast<int>(rows.size());
    std::array<Levers, 2> levers;
    for (int k = 0; k < pair.count; ++k) {
      levers[k] = levers_at(bodies, pair.bodies, pair.contacts[k].point);
      append_contact_row(rows, pair, pair.contacts[k], levers[k], bodies, settings, dt);
      warm_start.push_back(pair.contacts[k].lambda_normal);
      kinds.push_back(RowKind::contact);
    }
    const int tangents = friction_rows_per_contact(pair, settings);
    for (int t = 0; t < tangents; ++t) {
      for (int k = 0; k < pair.count; ++k) {
        const Contact& contact = pair.contacts[k];
        const bool in_plane = t == 0;
        const Vec3 u = in_plane ? lift(tangent_of(contact.normal)) : Vec3::UnitZ();
        append_friction_row(rows, pair, levers[k], u, first + k);
        warm_start.push_back(in_plane ? contact.lambda_tangent : 0.0);
        kinds.push_back(in_plane ? RowKind::friction : RowKind::out_of_plane_friction);
      }
    }
  }
}

void store_contact_lambdas(std::vector<ContactPair>& pairs, const std::vector<double>& lambda,
                           const ContactSettings& settings) {
  int first = 0;
  for (ContactPair& pair : pairs) {
    const int tangents = friction_rows_per_contact(pair, settings);
    for (int k = 0; k < pair.count; ++k) {
      pair.contacts[k].lambda_normal = lambda[first + k];
      pair.contacts[k].lambda_tangent = tangents > 0 ? lambda[first + pair.count + k] : 0.0;
    }
    first += pair.count * (1 + tangents);
  }
}

void position_targets(const std::vector<ContactPair>& pairs, const ContactSettings& settings,
                      double dt, std::vector<int>& rows, std::vector<double>& zeta) {
  rows.clear();
  zeta.clear();
  int first = 0;
  for (const ContactPair& pair : pairs) {
    for (int k = 0; k < pair.count; ++k) {
      const double separation = pair.contacts[k].separation;
      rows.push_back(first + k);
      zeta.push_back(gap_velocity(separation, dt) + push_out_velocity(separation, settings, dt));
    }
    first += pair.count * (1 + friction_rows_per_contact(pair, settings));
  }
}

void add_position_rows(const std::vector<ContactPair>& pairs,
                       const std::vector<ConstraintRow>& velocity_rows,
                       const ContactSettings& settings, double dt,
                       std::vector<ConstraintRow>& rows) {
  std::vector<int> contact_rows;
  std::vector<double> zeta;
  position_targets(pairs, settings, dt, contact_rows, zeta);
  for (size_t i = 0; i < contact_rows.size(); ++i) {
    rows.push_back(velocity_rows[contact_rows[i]]);
    rows.back().zeta = zeta[i];
  }
}

}  // namespace lamina
