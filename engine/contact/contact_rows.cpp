#include "contact/contact_rows.h"

#include <algorithm>

#include "constraints/jacobian_rows.h"
#include "constraints/mlcp.h"

namespace lamina {
namespace {

// The row of direction u at contact point c. A static body never moves (eq. 5-1), so it enters
// as the world and the row keeps only the other body's block, as eq. 5-8 writes it.
ConstraintRow direction_row(const std::vector<RigidBody>& bodies, const BodyPair& pair,
                            const Vec3& c, const Vec3& u) {
  const auto anchor = [&](int body) {
    return anchor_at(bodies, bodies[body].is_static() ? world : body, c);
  };
  // eq. 4-3: J = [−uᵀ  −(r1×u)ᵀ  uᵀ  (r2×u)ᵀ], r1 = c − x1, r2 = c − x2
  return point_row(bodies, anchor(pair.first), anchor(pair.second), u);
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

ConstraintRow contact_row(const ContactPair& pair, const Contact& contact,
                          const std::vector<RigidBody>& bodies, const ContactSettings& settings,
                          double dt) {
  ConstraintRow row = direction_row(bodies, pair.bodies, lift(contact.point), lift(contact.normal));
  // eq. 4-3, 5-10: 0 ≤ λ < ∞
  row.lambda_min = 0.0;
  row.zeta = gap_velocity(contact.separation, dt);
  if (settings.correction == PositionCorrection::baumgarte) {
    row.zeta += push_out_velocity(contact.separation, settings, dt);
  }
  // Restitution (beyond the text): a touching point approaching faster than v_e leaves at e times
  // its approach speed J V(t).
  const double approach = row_velocity(row, bodies);
  if (contact.separation <= 0.0 && approach < -settings.restitution_threshold) {
    row.zeta = std::max(row.zeta, -pair.restitution * approach);
  }
  return row;
}

ConstraintRow friction_row(const ContactPair& pair, const Contact& contact, const Vec3& u,
                           const std::vector<RigidBody>& bodies, int contact_row_index) {
  ConstraintRow row = direction_row(bodies, pair.bodies, lift(contact.point), u);
  // eq. 3-26 with λ± = ±μ λc, λc read from the contact row during the iterations
  row.friction_of = contact_row_index;
  row.mu = pair.friction;
  return row;
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
    for (int k = 0; k < pair.count; ++k) {
      rows.push_back(contact_row(pair, pair.contacts[k], bodies, settings, dt));
      warm_start.push_back(pair.contacts[k].lambda_normal);
      kinds.push_back(RowKind::contact);
    }
    const int tangents = friction_rows_per_contact(pair, settings);
    for (int t = 0; t < tangents; ++t) {
      for (int k = 0; k < pair.count; ++k) {
        const Contact& contact = pair.contacts[k];
        const bool in_plane = t == 0;
        const Vec3 u = in_plane ? lift(tangent_of(contact.normal)) : Vec3::UnitZ();
        rows.push_back(friction_row(pair, contact, u, bodies, first + k));
        warm_start.push_back(in_plane ? contact.lambda_tangent : 0.0);
        kinds.push_back(in_plane ? RowKind::friction : RowKind::out_of_plane_friction);
      }
    }
  }
}

void store_contact_lambdas(std::vector<ContactPair>& pairs, const Eigen::VectorXd& lambda,
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

void add_position_rows(const std::vector<ContactPair>& pairs, const std::vector<RigidBody>& bodies,
                       const ContactSettings& settings, double dt, std::vector<ConstraintRow>& rows) {
  for (const ContactPair& pair : pairs) {
    for (int k = 0; k < pair.count; ++k) {
      const Contact& contact = pair.contacts[k];
      ConstraintRow row =
          direction_row(bodies, pair.bodies, lift(contact.point), lift(contact.normal));
      row.lambda_min = 0.0;
      row.zeta = gap_velocity(contact.separation, dt) +
                 push_out_velocity(contact.separation, settings, dt);
      rows.push_back(row);
    }
  }
}

}  // namespace lamina
