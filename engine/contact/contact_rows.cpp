#include "contact/contact_rows.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <string>

#include "constraints/jacobian_rows.h"
#include "constraints/mlcp.h"
#include "kinematics/require.h"

namespace lamina {
namespace {

// A row as ConstraintRow's defaults make it: each row written starts as a copy of it.
const ConstraintRow blank_row;

// A pair's rows as they are written, before they go to the sink together: at most two contact
// rows and, per contact, a friction row along each of two tangents.
struct PairRows {
  static constexpr int most = 6;
  std::array<ConstraintRow, most> rows;
  int first = 0;  // the index rows[0] gets among all the rows
  int count = 0;  // rows written
  double* lambda = nullptr;  // every row's warm-start λ, by index

  ConstraintRow& at(int index) { return rows[static_cast<std::size_t>(index - first)]; }
};

// Writes the point row of direction u at the ends' contact point, with its λ_exp, as the pair's
// next row; returns its index.
int append_row(PairRows& slots, const RowEnds& ends, const Vec3& u, double lambda_exp) {
  assert(slots.count < PairRows::most);
  const int index = slots.first + slots.count++;
  ConstraintRow& row = slots.at(index);
  row = blank_row;
  write_point_row(ends, u, row);
  slots.lambda[index] = lambda_exp;
  return index;
}

// The velocity a cached point with a gap may approach at: 0 for the text (eq. 4-4's
// ζ = −β min(C, 0) is 0 for C > 0), or as fast as closes the gap within the step.
double gap_velocity(double separation, const ContactSettings& settings, double dt) {
  // a gap C > 0 may close within the step, no faster: J V ≥ −C/Δt (0 when touching)
  return settings.close_gaps && separation > 0.0 ? -separation / dt : 0.0;
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
  row.zeta = gap_velocity(contact.separation, settings, step.dt);
  if (settings.correction == PositionCorrection::baumgarte) {
    row.zeta += push_out_velocity(contact.separation, settings, step);
  }
  // Restitution (beyond the text): a touching point approaching faster than v_e leaves at e times
  // its approach speed J V(t). With e = 0 that asks for ζ ≥ 0, which ζ already is when touching.
  if (!settings.restitution || pair.restitution == 0.0 || contact.separation > 0.0) return;
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

// The rows a pair writes: a contact row per point and its friction rows, one per tangent for
// the pair's manifold of two points (FrictionRows::per_manifold) or per point.
int rows_of_pair(const ContactPair& pair, const ContactSettings& settings) {
  const bool one_row = settings.friction == FrictionRows::per_manifold && pair.count == 2;
  return pair.count + friction_rows_per_contact(pair, settings) * (one_row ? 1 : pair.count);
}

// Appends a friction row along u at the ends' point, bounded by ±μ times the λ of `count`
// contact rows from `contact_row` (eq. 3-26, λc read from them during the iterations).
int append_friction_row(PairRows& slots, const ContactPair& pair, const RowEnds& ends,
                        const Vec3& u, int contact_row, int count, double lambda_exp) {
  const int index = append_row(slots, ends, u, lambda_exp);
  ConstraintRow& row = slots.at(index);
  row.friction_of = contact_row;
  row.friction_count = count;
  row.mu = pair.friction;
  return index;
}

// The pitfall crude-friction: the pair's friction rows [first, last) bounded by ±μ m g per
// point they hold, m the mass of the moving body the contact holds up (the second, or the first
// when the second is static), whatever the normal force λc is: the text's cruder bound.
void crude_friction_bounds(PairRows& slots, int first, int last, const ContactPair& pair,
                           const std::vector<RigidBody>& bodies, const StepSettings& step) {
  const RigidBody& second = bodies[static_cast<std::size_t>(pair.bodies.second)];
  const RigidBody& held =
      second.is_static() ? bodies[static_cast<std::size_t>(pair.bodies.first)] : second;
  const double per_point = pair.friction * held.mass * step.gravity.norm();
  for (int i = first; i < last; ++i) {
    ConstraintRow& row = slots.at(i);
    const double bound = per_point * row.friction_count;
    row.friction_of = -1;
    row.friction_count = 1;
    row.lambda_min = -bound;
    row.lambda_max = bound;
  }
}

// The direction of friction row t: u1 = z × n in the plane, u2 = z.
Vec3 tangent(int t, const Vec2& normal) {
  return t == 0 ? lift(tangent_of(normal)) : Vec3::UnitZ();
}

}  // namespace

void validate(const ContactSettings& s) {
  require(std::isfinite(s.slop) && s.slop >= 0.0,
          "contact settings: slop must be finite and ≥ 0, got " + std::to_string(s.slop));
  require(std::isfinite(s.restitution_threshold) && s.restitution_threshold >= 0.0,
          "contact settings: restitution_threshold must be finite and ≥ 0, got " +
              std::to_string(s.restitution_threshold));
}

namespace {

// Writes one pair's rows into `slots` (from its `first` on) and records where they went.
void write_pair_rows(ContactPair& pair, const std::vector<RigidBody>& bodies,
                     const ContactSettings& settings, const StepSettings& step, PairRows& slots) {
  slots.count = 0;
  pair.rows.first = slots.first;
  std::array<RowEnds, 2> ends;
  for (int k = 0; k < pair.count; ++k) {
    Contact& contact = pair.contacts[k];
    // r1 = c − x1, r2 = c − x2
    ends[k] = ends_at_point(bodies, pair.bodies.first, pair.bodies.second, lift(contact.point));
    contact.row = append_row(slots, ends[k], lift(contact.normal), contact.lambda_normal);
    write_contact_row(slots.at(contact.row), pair, contact, bodies, settings, step);
  }
  for (int k = 0; k < pair.count; ++k) pair.contacts[k].friction_rows = {-1, -1};
  const int tangents = friction_rows_per_contact(pair, settings);
  const int first_friction_row = slots.first + slots.count;
  const bool one_row = settings.friction == FrictionRows::per_manifold && pair.count == 2;
  for (int t = 0; t < tangents; ++t) {
    if (one_row) {
      Contact& a = pair.contacts[0];
      Contact& b = pair.contacts[1];
      // the manifold's middle and normal; its contact rows are a.row and a.row + 1
      const Vec2 middle = 0.5 * (a.point + b.point);
      const Vec2 sum = a.normal + b.normal;  // opposite normals cannot share a tangent
      const double length = sum.norm();
      // sum / |sum|: Eigen's normalized(), without taking the root a second time
      const Vec2 normal = length > 1e-9 ? Vec2(sum / length) : a.normal;
      const RowEnds at_middle =
          ends_at_point(bodies, pair.bodies.first, pair.bodies.second, lift(middle));
      a.friction_rows[t] = b.friction_rows[t] =
          append_friction_row(slots, pair, at_middle, tangent(t, normal), a.row, 2,
                              t == 0 ? a.lambda_tangent + b.lambda_tangent : 0.0);
      continue;
    }
    for (int k = 0; k < pair.count; ++k) {
      Contact& contact = pair.contacts[k];
      contact.friction_rows[t] =
          append_friction_row(slots, pair, ends[k], tangent(t, contact.normal), contact.row, 1,
                              t == 0 ? contact.lambda_tangent : 0.0);
    }
  }
  if (step.pitfalls.has(Pitfall::crude_friction)) {
    crude_friction_bounds(slots, first_friction_row, slots.first + slots.count, pair, bodies, step);
  }
  pair.rows.count = slots.count;
}

// Keeps a pair's solved λ in its contacts (store_contact_lambdas).
void store_pair_lambdas(ContactPair& pair, const double* lambda) {
  for (int k = 0; k < pair.count; ++k) {
    Contact& contact = pair.contacts[k];
    contact.lambda_normal = lambda[contact.row];
    contact.lambda_tangent = contact.friction_rows[0] >= 0 ? lambda[contact.friction_rows[0]] : 0.0;
  }
  const bool one_row = pair.count == 2 && pair.contacts[0].friction_rows[0] >= 0 &&
                       pair.contacts[0].friction_rows[0] == pair.contacts[1].friction_rows[0];
  if (!one_row) return;
  // the manifold's friction λ shared in proportion to the points' λc (halves when both are 0)
  Contact& a = pair.contacts[0];
  Contact& b = pair.contacts[1];
  const double total = a.lambda_normal + b.lambda_normal;
  const double share = total > 0.0 ? a.lambda_normal / total : 0.5;
  const double friction = a.lambda_tangent;
  a.lambda_tangent = share * friction;
  b.lambda_tangent = friction - a.lambda_tangent;
}

}  // namespace

ContactRows::ContactRows(std::vector<ContactPair>& pairs, const std::vector<RigidBody>& bodies,
                         const ContactSettings& settings, const StepSettings& step,
                         std::vector<double>& lambda)
    : pairs_(pairs), bodies_(bodies), settings_(settings), step_(step), lambda_(lambda) {}

std::size_t ContactRows::count(int t, int runs) {
  const auto [first, last] = share_of(pairs_.size(), t, runs);
  std::size_t count = 0;
  for (std::size_t p = first; p < last; ++p) {
    count += static_cast<std::size_t>(rows_of_pair(pairs_[p], settings_));
  }
  return count;
}

void ContactRows::begin(std::size_t total) { lambda_.resize(total); }

void ContactRows::write(int t, int runs, RowSink& sink) {
  PairRows slots;
  slots.lambda = lambda_.data();
  const auto [first, last] = share_of(pairs_.size(), t, runs);
  for (std::size_t p = first; p < last; ++p) {
    slots.first = sink.next();
    write_pair_rows(pairs_[p], bodies_, settings_, step_, slots);
    // rows_of_pair counts what write_pair_rows writes
    assert(slots.count == rows_of_pair(pairs_[p], settings_));
    if (!sink.put(slots.rows.data(), slots.count)) return;
  }
}

namespace {

// Rows put into a vector sized for them, from `first` on.
class RowVector final : public RowSink {
 public:
  RowVector(std::vector<ConstraintRow>& rows, int first) : RowSink(first), rows_(rows) {}
  bool put(const ConstraintRow* rows, int count) override {
    std::copy(rows, rows + count, rows_.begin() + next_);
    next_ += count;
    return true;
  }

 private:
  std::vector<ConstraintRow>& rows_;
};

}  // namespace

void add_contact_rows(std::vector<ContactPair>& pairs, const std::vector<RigidBody>& bodies,
                      const ContactSettings& settings, const StepSettings& step,
                      std::vector<ConstraintRow>& rows, std::vector<double>& lambda,
                      Workers* workers) {
  // Each run of the workers writes a run of the pairs. Its rows' place is counted first, so
  // that the runs write side by side into rows sized for all of them at once.
  ContactRows writer(pairs, bodies, settings, step, lambda);
  const int runs = runs_on(workers);
  const RunStarts first_row = run_starts(workers, [&](int t) { return writer.count(t, runs); });
  const std::size_t total = first_row[static_cast<std::size_t>(runs)];
  writer.begin(total);
  rows.resize(total);
  run_on(workers, [&](int t) {
    RowVector sink(rows, static_cast<int>(first_row[static_cast<std::size_t>(t)]));
    writer.write(t, runs, sink);
  });
}

void store_contact_lambdas(std::vector<ContactPair>& pairs, const double* lambda,
                           Workers* workers) {
  const int runs = runs_on(workers);
  run_on(workers, [&](int t) {
    const auto [first, last] = share_of(pairs.size(), t, runs);
    for (std::size_t p = first; p < last; ++p) store_pair_lambdas(pairs[p], lambda);
  });
}

void position_targets(const std::vector<ContactPair>& pairs, const ContactSettings& settings,
                      const StepSettings& step, std::vector<int>& rows, std::vector<double>& zeta,
                      Workers* workers) {
  // Each run's targets go after the runs before it: its contacts are counted first.
  const int runs = runs_on(workers);
  const RunStarts first_target = run_starts(workers, [&](int t) {
    const auto [first, last] = share_of(pairs.size(), t, runs);
    std::size_t count = 0;
    for (std::size_t p = first; p < last; ++p) count += static_cast<std::size_t>(pairs[p].count);
    return count;
  });
  rows.resize(first_target[static_cast<std::size_t>(runs)]);
  zeta.resize(first_target[static_cast<std::size_t>(runs)]);
  run_on(workers, [&](int t) {
    const auto [first, last] = share_of(pairs.size(), t, runs);
    std::size_t next = first_target[static_cast<std::size_t>(t)];
    for (std::size_t p = first; p < last; ++p) {
      for (int k = 0; k < pairs[p].count; ++k, ++next) {
        const Contact& contact = pairs[p].contacts[k];
        rows[next] = contact.row;
        zeta[next] = gap_velocity(contact.separation, settings, step.dt) +
                     push_out_velocity(contact.separation, settings, step);
      }
    }
  });
}

}  // namespace lamina
