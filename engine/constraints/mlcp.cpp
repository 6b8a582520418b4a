#include "constraints/mlcp.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lamina {
namespace {

// M⁻¹ J_b for one body's block in the layout of N components (eq. 3-12, the text's Convert).
// In the plane, where I⁻¹ turns z into itself, it is [m⁻¹ J_x, m⁻¹ J_y, (I⁻¹)_zz J_ωz]: the
// numbers of the 6-vector form without its zero terms.
template <int N>
Block<N> convert(const RigidBody& body, const Block<N>& block);
template <>
Block<6> convert<6>(const RigidBody& body, const Block<6>& block) {
  return inverse_mass_times(body, block);
}
template <>
Block<3> convert<3>(const RigidBody& body, const Block<3>& block) {
  // eq. 3-12 in the plane: M⁻¹ = diag(m⁻¹, m⁻¹, (I⁻¹)_zz) on [v_x v_y ω_z]
  return Block<3>(body.inverse_mass * block[0], body.inverse_mass * block[1],
                  body.inverse_inertia_world(2, 2) * block[2]);
}

// Packs row i of the MLCP, in place (packed rows keep their memory from step to step): its J
// and B blocks, η_i, 1/d_i, ζ_i and bounds. N = 3 asks the row and its bodies to lie in the
// plane (J's and B's v_z, ω_x, ω_y zero); its numbers are then those of N = 6, cut.
template <int N>
void pack_row(const std::vector<RigidBody>& bodies, const ConstraintRow& row,
              const std::vector<Vec6>& unconstrained, double dt, PackedRow<N>& packed) {
  assert(row.Jmap[0] >= 0 && row.Jmap[0] != row.Jmap[1]);  // one or two bodies, never the same
  packed.map = row.Jmap;
  for (int k = 0; k < 2; ++k) {
    packed.J[k] = cut<N>(row.Jsp[k]);
    // the text's Convert: Bᵀ_i = J_i M⁻¹, block by block
    packed.B[k] = row.Jmap[k] < 0 ? Block<N>::Zero().eval() : convert<N>(bodies[row.Jmap[k]], packed.J[k]);
  }
  const bool two = row.Jmap[1] >= 0;
  // d_i = J_i · B_i
  const double d = row_dot<N>(packed.J, packed.B[0], packed.B[1], true);
  // A row moves a body (jacobian_rows.h), so d_i = J_i M⁻¹ J_iᵀ > 0 and 1/d_i is finite.
  assert(d > 0.0);
  packed.inverse_d = 1.0 / d;
  // J_i (V/Δt + M⁻¹ F_ext)
  const Block<N> u0 = cut<N>(unconstrained[row.Jmap[0]]);
  const double j_u = row_dot<N>(packed.J, u0, two ? cut<N>(unconstrained[row.Jmap[1]]) : u0, two);
  // eq. 3-16: η = ζ/Δt − J (V/Δt + M⁻¹ F_ext)
  packed.eta = row.zeta / dt - j_u;
  packed.zeta = row.zeta;
  packed.lambda_min = row.lambda_min;
  packed.lambda_max = row.lambda_max;
  packed.friction_of = row.friction_of;
  packed.friction_count = row.friction_count;
  packed.mu = row.mu;
}

// Whether a body's I⁻¹ turns the z axis into itself, so that B = M⁻¹ Jᵀ of a row in the plane
// (J's v_z, ω_x, ω_y zero) lies in the plane too.
bool inertia_in_plane(const RigidBody& body) {
  return body.inverse_inertia_world(0, 2) == 0.0 && body.inverse_inertia_world(1, 2) == 0.0;
}

// Whether two rows are on the same bodies, in the same order (compared element by element:
// std::array's == becomes a call to memcmp here, a tenth of the packing's instructions).
bool same_bodies(const std::array<int, 2>& a, const std::array<int, 2>& b) {
  return a[0] == b[0] && a[1] == b[1];
}

// Whether a friction row — row i on bodies `map`, bounded by rows friction_of ..
// friction_of + count − 1 — has its contact rows before it on its own bodies, map_at(k) giving
// row k's bodies; true for a row that is no friction row (friction_of < 0).
template <class MapAt>
bool on_own_bodies(const std::array<int, 2>& map, int friction_of, int count, std::size_t i,
                   MapAt&& map_at) {
  for (int k = 0; friction_of >= 0 && k < count; ++k) {
    const int contact = friction_of + k;
    if (static_cast<std::size_t>(contact) >= i || !same_bodies(map_at(contact), map)) return false;
  }
  return true;
}

template <int N>
const PackedRow<N>& row_at(const PackedRows<N>& rows, int i) {
  assert(i >= 0 && i < static_cast<int>(rows.size()));
  return rows[static_cast<std::size_t>(i)];
}

}  // namespace

Vec6 inverse_mass_times(const RigidBody& body, const Vec6& block) {
  Vec6 result;
  // eq. 3-12: M⁻¹ = diag(m⁻¹ E, I⁻¹) for this body
  result.head<3>() = body.inverse_mass * block.head<3>();
  result.tail<3>() = body.inverse_inertia_world * block.tail<3>();
  return result;
}

Vec6 velocity_of(const RigidBody& body) {
  Vec6 v;
  v.head<3>() = body.v;
  v.tail<3>() = body.angular_velocity;
  return v;
}

Vec6 external_force_of(const RigidBody& body) {
  Vec6 f;
  f.head<3>() = body.force;
  f.tail<3>() = body.torque;
  return f;
}

void unconstrained_velocities(const std::vector<RigidBody>& bodies, double dt,
                              std::vector<Vec6>& out, Workers* workers) {
  out.resize(bodies.size());
  const int runs = runs_on(workers);
  run_on(workers, [&](int t) {
    const auto [first, last] = share_of(bodies.size(), t, runs);
    for (size_t b = first; b < last; ++b) {
      // eq. 3-16: V/Δt + M⁻¹ F_ext, the bracket of η, body by body
      out[b] = velocity_of(bodies[b]) / dt +
               inverse_mass_times(bodies[b], external_force_of(bodies[b]));
    }
  });
}

double row_velocity(const ConstraintRow& row, const std::vector<RigidBody>& bodies) {
  const Vec6 v0 = velocity_of(bodies[row.Jmap[0]]);
  const bool two = !row.is_one_body();
  // eq. 5-4, 5-5: J_i V
  return row_dot<6>(row.Jsp, v0, two ? velocity_of(bodies[row.Jmap[1]]) : v0, two);
}

template <class Pack>
void Mlcp::pack_in_runs(std::size_t count, Workers* workers, Pack&& pack) {
  const int runs = runs_on(workers);
  groups_of_run_.resize(runs);
  friction_own_in_run_.assign(static_cast<std::size_t>(runs), 1);
  const auto pack_run = [&](int t) {
    const auto [first, last] = share_of(count, t, runs);
    std::vector<RowGroup>& groups = groups_of_run_[t];
    groups.clear();
    for (std::size_t i = first; i < last; ++i) {
      if (!pack(i, groups)) friction_own_in_run_[t] = 0;
    }
  };
  run_on(workers, pack_run);
  groups_.clear();
  friction_on_own_bodies_ = true;
  for (int t = 0; t < runs; ++t) {
    groups_.insert(groups_.end(), groups_of_run_[t].begin(), groups_of_run_[t].end());
    friction_on_own_bodies_ = friction_on_own_bodies_ && friction_own_in_run_[t] != 0;
  }
  groups_.push_back({static_cast<int>(count), {-1, -1}});
}

void Mlcp::assemble(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                    const std::vector<Vec6>& unconstrained, double dt, Workers* workers) {
  // the layout: planar when every row and every body's I⁻¹ keep to the plane (each run of the
  // workers checks its bodies, then its rows)
  inertia_in_plane_.resize(bodies.size());
  const int runs = runs_on(workers);
  planar_in_run_.assign(static_cast<std::size_t>(runs), 1);
  const auto check_bodies = [&](int t) {
    const auto [first_body, last_body] = share_of(bodies.size(), t, runs);
    for (size_t b = first_body; b < last_body; ++b) inertia_in_plane_[b] = inertia_in_plane(bodies[b]);
  };
  const auto check_rows = [&](int t) {
    const auto [first, last] = share_of(rows.size(), t, runs);
    planar_in_run_[t] = std::all_of(rows.begin() + first, rows.begin() + last, [&](const ConstraintRow& row) {
      return in_plane(row.Jsp[0]) && in_plane(row.Jsp[1]) && inertia_in_plane_[row.Jmap[0]] &&
             (row.is_one_body() || inertia_in_plane_[row.Jmap[1]]);
    });
  };
  run_on(workers, check_bodies);
  run_on(workers, check_rows);
  planar_ = std::all_of(planar_in_run_.begin(), planar_in_run_.end(), [](unsigned char p) { return p != 0; });
  body_count_ = static_cast<int>(bodies.size());
  visit_mutable([&](auto& packed) {
    packed.resize(rows.size());
    pack_in_runs(rows.size(), workers, [&](std::size_t i, std::vector<RowGroup>& groups) {
      pack_row(bodies, rows[i], unconstrained, dt, packed[i]);
      // the groups and the friction rows' bodies, from the rows as written (read-only: a row
      // of another run may not be packed yet)
      if (i == 0 || !same_bodies(rows[i].Jmap, rows[i - 1].Jmap)) {
        groups.push_back({static_cast<int>(i), rows[i].Jmap});
      }
      return on_own_bodies(rows[i].Jmap, rows[i].friction_of, rows[i].friction_count, i,
                           [&](int k) { return rows[k].Jmap; });
    });
  });
}

template <class Finish>
void Mlcp::select_rows(const Mlcp& from, const std::vector<int>& rows, Workers* workers,
                       Finish&& finish) {
  planar_ = from.planar_;
  body_count_ = from.body_count_;
  auto select = [&](const auto& source, auto& packed) {
    packed.resize(rows.size());
    pack_in_runs(rows.size(), workers, [&](std::size_t i, std::vector<RowGroup>& groups) {
      const auto& row = source[static_cast<std::size_t>(rows[i])];
      packed[i] = row;
      if (i == 0 || !same_bodies(row.map, source[static_cast<std::size_t>(rows[i - 1])].map)) {
        groups.push_back({static_cast<int>(i), row.map});
      }
      if (row.friction_of >= 0) {
        // the new index of its first contact row (rows ascend: a binary search)
        const auto at = std::lower_bound(rows.begin(), rows.end(), row.friction_of);
        assert(at != rows.end() && *at == row.friction_of);
        packed[i].friction_of = static_cast<int>(at - rows.begin());
      }
      finish(packed[i], i);
      return on_own_bodies(row.map, row.friction_of, row.friction_count,
                           static_cast<std::size_t>(rows[i]), [&](int k) { return source[k].map; });
    });
  };
  if (planar_) {
    select(from.planar_rows_, planar_rows_);
  } else {
    select(from.general_rows_, general_rows_);
  }
}

void Mlcp::assemble_subset(const Mlcp& from, const std::vector<int>& rows, Workers* workers) {
  select_rows(from, rows, workers, [](auto& /*row*/, std::size_t /*i*/) {});
}

void Mlcp::assemble_rows_of(const Mlcp& from, const std::vector<int>& rows,
                            const std::vector<double>& zeta, double dt, Workers* workers) {
  select_rows(from, rows, workers, [&](auto& row, std::size_t i) {
    row.zeta = zeta[i];
    // eq. 3-16 for bodies at rest under no force: η = ζ/Δt
    row.eta = zeta[i] / dt;
  });
}

int Mlcp::row_count() const {
  return visit([](const auto& rows) { return static_cast<int>(rows.size()); });
}

std::array<int, 2> Mlcp::bodies_of(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).map; });
}

Vec6 Mlcp::jacobian(int i, int k) const {
  return visit([&](const auto& rows) { return widen(row_at(rows, i).J[k]); });
}

Vec6 Mlcp::b_block(int i, int k) const {
  return visit([&](const auto& rows) { return widen(row_at(rows, i).B[k]); });
}

double Mlcp::zeta(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).zeta; });
}

double Mlcp::eta(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).eta; });
}

double Mlcp::d(int i) const {
  // d_i = J_i · B_i, as assembled
  return visit([&](const auto& rows) {
    const auto& row = row_at(rows, i);
    return row_dot(row.J, row.B[0], row.B[1], true);
  });
}

int Mlcp::friction_of(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).friction_of; });
}

int Mlcp::friction_count(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).friction_count; });
}

double Mlcp::mu(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).mu; });
}

std::array<double, 2> Mlcp::bounds(int i, const double* lambda) const {
  return visit([&](const auto& rows) { return bounds_of(row_at(rows, i), lambda); });
}

Eigen::VectorXd Mlcp::slack(const double* lambda) const {
  return visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    std::vector<Block<N>> a;
    transpose_multiply(rows, body_count_, lambda, a);
    Eigen::VectorXd w(static_cast<Eigen::Index>(rows.size()));
    // eq. 3-23: W = J B λ − η
    for (size_t i = 0; i < rows.size(); ++i) w[static_cast<Eigen::Index>(i)] = row_dot(rows[i], a) - rows[i].eta;
    return w;
  });
}

double Mlcp::residual(const double* lambda) const {
  const Eigen::VectorXd w = slack(lambda);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    const auto [lo, hi] = bounds(static_cast<int>(i), lambda);
    // eq. 3-24: W = 0 inside the bounds, W ≥ 0 at λ⁻, W ≤ 0 at λ⁺
    double violation = w[i];
    if (lambda[i] <= lo) violation = std::min(w[i], 0.0);
    if (lambda[i] >= hi) violation = std::max(w[i], 0.0);
    if (lo == hi) violation = 0.0;
    sum += violation * violation;
  }
  return std::sqrt(sum);
}

double Mlcp::row_times(int i, const std::vector<Vec6>& per_body) const {
  return visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    const auto& row = row_at(rows, i);
    const Block<N> x0 = cut<N>(per_body[row.map[0]]);
    return row_dot<N>(row.J, x0, row.two_bodies() ? cut<N>(per_body[row.map[1]]) : x0,
                      row.two_bodies());
  });
}

namespace {

// Adds λ J_b to body b's force and torque: all six components, or v_x, v_y, ω_z in the plane.
void add_wrench(RigidBody& body, double lambda, const Block<6>& J) {
  body.force += lambda * J.head<3>();
  body.torque += lambda * J.tail<3>();
}
void add_wrench(RigidBody& body, double lambda, const Block<3>& J) {
  body.force.x() += lambda * J[0];
  body.force.y() += lambda * J[1];
  body.torque.z() += lambda * J[2];
}

}  // namespace

void Mlcp::add_constraint_forces(std::vector<RigidBody>& bodies, const double* lambda,
                                 Workers* workers) const {
  const int runs = runs_on(workers);
  if (runs == 1) {
    visit([&](const auto& rows) {
      // eq. 3-11: F_c = Jᵀ λ
      for_each_force(rows, lambda, [&](int body, double l, const auto& J) {
        add_wrench(bodies[body], l, J);
      });
    });
    return;
  }
  // Each run adds to its share of the bodies only (the share each run integrates), taking the
  // groups that touch them in row order: every body's sum in the one-thread order.
  run_on(workers, [&](int t) {
    const std::pair<std::size_t, std::size_t> share = share_of(bodies.size(), t, runs);
    const std::size_t first = share.first;  // named, not bound: a lambda may not capture a binding
    const std::size_t last = share.second;
    const auto own = [&](int body) {
      return body >= 0 && static_cast<std::size_t>(body) >= first && static_cast<std::size_t>(body) < last;
    };
    visit([&](const auto& rows) {
      for (std::size_t g = 0; g + 1 < groups_.size(); ++g) {
        const std::array<int, 2> pair = groups_[g].bodies;
        if (!own(pair[0]) && !own(pair[1])) continue;
        // eq. 3-11: F_c = Jᵀ λ, this run's blocks of it
        for_each_force(rows, lambda, groups_[g].first, groups_[g + 1].first,
                       [&](int body, double l, const auto& J) {
                         if (own(body)) add_wrench(bodies[body], l, J);
                       });
      }
    });
  });
}

Vec6 Mlcp::constraint_wrench(int body, const double* lambda) const {
  Vec6 wrench = Vec6::Zero();
  visit([&](const auto& rows) {
    // eq. 3-11, 5-9: body b's block of F_c = Jᵀ λ
    for_each_force(rows, lambda, [&](int b, double l, const auto& J) {
      if (b == body) wrench += l * widen(J);
    });
  });
  return wrench;
}

Mlcp assemble_mlcp(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                   double dt) {
  std::vector<Vec6> unconstrained;
  unconstrained_velocities(bodies, dt, unconstrained);
  Mlcp mlcp;
  mlcp.assemble(bodies, rows, unconstrained, dt);
  return mlcp;
}

}  // namespace lamina
