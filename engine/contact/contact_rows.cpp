#include "contact/contact_rows.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "constraints/jacobian_rows.h"
#include "constraints/mlcp.h"
#include "kinematics/require.h"

namespace lamina {
namespace {

// A row as ConstraintRow's defaults make it: new rows are copied from it, which costs less than
// value-initialising each one in place.
const ConstraintRow blank_row;

// Appends the point row of direction u at the ends' contact point; returns its index.
int append_row(std::vector<ConstraintRow>& rows, const RowEnds& ends, const Vec3& u) {
  write_point_row(ends, u, rows.emplace_back(blank_row));
  return static_cast<int>(rows.size()) - 1;
}

// The velocity a cached point with a gap may approach at.
double gap_velocity(double separation, double dt) {
  // a gap C > 0 may close within the step, no faster: J V ≥ −C/Δt (0 when touching)
  return separation > 0.0 ? -separation / dt : 0.0;
}

// The velocity that pushes a penetration out, a slop deep being left alone.
double push_out_velocity(double separation, const ContactSettings& settings,
                         const StepSettings& step) {
  // eq. 4-4, 4-5: J V ≥ ζ/Δt, ζ = −β min(C, 0); here with C + slop
  return -step.beta * std::min(separation + settings.slop, 0.0) / step.dt;
}

void write_contact_row(ConstraintRow& row, const ContactPair& pair, const Contact& contact,
                       const std::vector<RigidBody>& bodies, const ContactSettings& settings,
                       const StepSettings& step) {
  // eq. 4-3, 5-10: 0 ≤ λ < ∞
  row.lambda_min = 0.0;
  row.zeta = gap_velocity(contact.separation, step.dt);
  if (settings.correction == PositionCorrection::baumgarte) {
    row.zeta += push_out_velocity(contact.separation, settings, step);
  }
  // Restitution (beyond the text): a touching point approaching faster than v_e leaves at e times
  // its approach speed J V(t). With e = 0 that asks for ζ ≥ 0, which ζ already is when touching.
  if (pair.restitution == 0.0 || contact.separation > 0.0) return;
  const double approach = row_velocity(row, bodies);
  if (approach < -settings.restitution_threshold) {
    row.zeta = std::max(row.zeta, -pair.restitution * approach);
  }
}

// Friction rows per contact of a pair: none when μ = 0 (their bounds would be ±0), u1, and u2
// when asked for.
int friction_rows_per_contact(const ContactPair& pair, const ContactSettings& settings) {
  if (pair.friction == 0.0) return 0;
  return settings.out_of_plane_friction ? 2 : 1;
}

}  // namespace

void validate(const ContactSettings& s) {
  require(std::isfinite(s.slop) && s.slop >= 0.0,
          "contact settings: slop must be finite and ≥ 0, got " + std::to_string(s.slop));
  require(std::isfinite(s.restitution_threshold) && s.restitution_threshold >= 0.0,
          "contact settings: restitution_threshold must be finite and ≥ 0, got " +
              std::to_string(s.restitution_threshold));
}

void add_contact_rows(std::vector<ContactPair>& pairs, const std::vector<RigidBody>& bodies,
                      const ContactSettings& settings, const StepSettings& step,
                      std::vector<ConstraintRow>& rows, std::vector<double>& lambda) {
  for (ContactPair& pair : pairs) {
    pair.rows.first = static_cast<int>(rows.size());
    std::array<RowEnds, 2> ends;
    for (int k = 0; k < pair.count; ++k) {
      Contact& contact = pair.contacts[k];
      // r1 = c − x1, r2 = c − x2
      ends[k] = ends_at_point(bodies, pair.bodies.first, pair.bodies.second, lift(contact.point));
      contact.row = append_row(rows, ends[k], lift(contact.normal));
      write_contact_row(rows.back(), pair, contact, bodies, settings, step);
      lambda.push_back(contact.lambda_normal);
    }
    const int tangents = friction_rows_per_contact(pair, settings);
    for (int t = 0; t < 2; ++t) {
      for (int k = 0; k < pair.count; ++k) {
        Contact& contact = pair.contacts[k];
        contact.friction_rows[t] = -1;
        if (t >= tangents) continue;
        const bool in_plane = t == 0;
        const Vec3 u = in_plane ? lift(tangent_of(contact.normal)) : Vec3::UnitZ();
        contact.friction_rows[t] = append_row(rows, ends[k], u);
        // eq. 3-26 with λ± = ±μ λc, λc read from the contact row during the iterations
        rows.back().friction_of = contact.row;
        rows.back().mu = pair.friction;
        lambda.push_back(in_plane ? contact.lambda_tangent : 0.0);
      }
    }
    pair.rows.count = static_cast<int>(rows.size()) - pair.rows.first;
  }
}

void store_contact_lambdas(std::vector<ContactPair>& pairs, const double* lambda) {
  for (ContactPair& pair : pairs) {
    for (int k = 0; k < pair.count; ++k) {
      Contact& contact = pair.contacts[k];
      contact.lambda_normal = lambda[contact.row];
      contact.lambda_tangent = contact.friction_rows[0] >= 0 ? lambda[contact.friction_rows[0]] : 0.0;
    }
  }
}

void position_targets(const std::vector<ContactPair>& pairs, const ContactSettings& settings,
                      const StepSettings& step, std::vector<int>& rows, std::vector<double>& zeta) {
  rows.clear();
  zeta.clear();
  for (const ContactPair& pair : pairs) {
    for (int k = 0; k < pair.count; ++k) {
      const Contact& contact = pair.contacts[k];
      rows.push_back(contact.row);
      zeta.push_back(gap_velocity(contact.separation, step.dt) +
                     push_out_velocity(contact.separation, settings, step));
    }
  }
}

}  // namespace lamina
