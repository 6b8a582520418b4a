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
// plane (J's and B's v_z, ω_x, ω_y zero); its numbers are then those of N = 6, cut. Always
// inlined into its two callers (called, 0.5 M more instructions a step of pyramid:20).
template <int N>
[[gnu::always_inline]] inline void pack_row(const std::vector<RigidBody>& bodies,
                                            const ConstraintRow& row,
                                            const std::vector<Vec6>& unconstrained, double dt,
                                            PackedRow<N>& packed) {
  assert(row.Jmap[0] >= 0 && row.Jmap[0] != row.Jmap[1]);  // one or two bodies, never the same
  packed.map = row.Jmap;
  for (int k = 0; k < 2; ++k) {
    packed.J[k] = cut<N>(row.Jsp[k]);
    // the text's Convert: Bᵀ_i = J_i M⁻¹, block by block
    packed.B[k] = row.Jmap[k] < 0 ? Block<N>::Zero().eval()
                                  : convert<N>(bodies[row.Jmap[k]], packed.J[k]);
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
  copy_row_scalars(row, packed);
}

// Whether a body's I⁻¹ turns the z axis into itself, so that B = M⁻¹ Jᵀ of a row in the plane
// (J's v_z, ω_x, ω_y zero) lies in the plane too.
bool inertia_in_plane(const RigidBody& body) {
  return body.inverse_inertia_world(0, 2) == 0.0 && body.inverse_inertia_world(1, 2) == 0.0;
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
void Mlcp::pack_in_runs(std::size_t first, std::size_t count, Workers* workers, Pack&& pack) {
  if (count == 0) return;  // no groups: nothing to hand the threads (a World without joints)
  const int runs = runs_on(workers);
  groups_of_run_.resize(runs);
  friction_own_in_run_.assign(static_cast<std::size_t>(runs), 1);
  const auto pack_run = [&](int t) {
    const auto [begin, end] = share_of(count, t, runs);
    std::vector<RowGroup>& groups = groups_of_run_[t];
    groups.clear();
    for (std::size_t i = first + begin; i < first + end; ++i) {
      if (!pack(i, groups)) friction_own_in_run_[t] = 0;
    }
  };
  run_on(workers, pack_run);
  for (int t = 0; t < runs; ++t) {
    add_groups(groups_of_run_[t]);
    friction_on_own_bodies_ = friction_on_own_bodies_ && friction_own_in_run_[t] != 0;
  }
}

void Mlcp::add_groups(const std::vector<RowGroup>& groups) {
  auto from = groups.begin();
  const bool joins = from != groups.end() && !groups_.empty() &&
                     same_bodies(groups_.back().bodies, from->bodies);
  if (joins) ++from;
  groups_.insert(groups_.end(), from, groups.end());
}

namespace {

// Whether a row and its bodies' I⁻¹ keep to the plane, so that it can be packed in the planar
// layout. Inlined: looked at for every row a step writes.
[[gnu::always_inline]] inline bool row_in_plane(
    const ConstraintRow& row, const std::vector<unsigned char>& inertia_in_plane) {
  return in_plane(row.Jsp[0]) && in_plane(row.Jsp[1]) && inertia_in_plane[row.Jmap[0]] &&
         (row.is_one_body() || inertia_in_plane[row.Jmap[1]]);
}

// A run of the rows a RowWriter writes, packed as they come into packed rows from `first` on:
// the groups that start in the run, and whether each friction row has its contact rows before
// it on its own bodies in the run (a contact's always do). For N = 3, a row out of the plane
// stops the packing and the writing (in_plane() false: the rows are then written again and
// packed in the general layout).
template <int N>
class PackingSink final : public RowSink {
 public:
  PackingSink(int first, PackedRows<N>& packed, const std::vector<RigidBody>& bodies,
              const std::vector<unsigned char>& inertia_in_plane,
              const std::vector<Vec6>& unconstrained, double dt, std::vector<RowGroup>& groups)
      : RowSink(first), first_(first), packed_(packed), bodies_(bodies),
        inertia_in_plane_(inertia_in_plane), unconstrained_(unconstrained), dt_(dt),
        groups_(groups) {}

  bool put(const ConstraintRow* rows, int count) override {
    if (!in_plane_) return false;  // it takes no more
    for (int k = 0; k < count; ++k, ++next_) {
      const ConstraintRow& row = rows[k];
      if constexpr (N == 3) {
        if (!row_in_plane(row, inertia_in_plane_)) {
          in_plane_ = false;
          return false;
        }
      }
      pack_row<N>(bodies_, row, unconstrained_, dt_, packed_[static_cast<std::size_t>(next_)]);
      if (groups_.empty() || !same_bodies(row.Jmap, groups_.back().bodies)) {
        groups_.push_back({next_, row.Jmap});
      }
      // a row of another run may not be packed yet: one bounded by it is taken as not own
      own_ = own_ && on_own_bodies(row.Jmap, row.friction_of, row.friction_count,
                                   static_cast<std::size_t>(next_), [&](int c) {
                                     return c >= first_ ? packed_[static_cast<std::size_t>(c)].map
                                                        : std::array<int, 2>{-2, -2};
                                   });
    }
    return true;
  }
  bool in_plane() const { return in_plane_; }
  bool friction_on_own_bodies() const { return own_; }

 private:
  int first_;
  PackedRows<N>& packed_;
  const std::vector<RigidBody>& bodies_;
  const std::vector<unsigned char>& inertia_in_plane_;
  const std::vector<Vec6>& unconstrained_;
  double dt_;
  std::vector<RowGroup>& groups_;
  bool in_plane_ = true;
  bool own_ = true;
};

// No rows: the writer of the assembly of a vector of rows alone.
class NoRows final : public RowWriter {
 public:
  std::size_t count(int /*t*/, int /*runs*/) override { return 0; }
  void begin(std::size_t /*total*/) override {}
  void write(int /*t*/, int /*runs*/, RowSink& /*sink*/) override {}
};

}  // namespace

template <int N>
bool Mlcp::pack_written(PackedRows<N>& packed, const std::vector<RigidBody>& bodies,
                        RowWriter& written, const RunStarts& starts,
                        const std::vector<Vec6>& unconstrained, double dt, Workers* workers) {
  const int runs = runs_on(workers);
  groups_of_run_.resize(runs);
  friction_own_in_run_.assign(static_cast<std::size_t>(runs), 1);
  planar_in_run_.assign(static_cast<std::size_t>(runs), 1);
  run_on(workers, [&](int t) {
    std::vector<RowGroup>& groups = groups_of_run_[t];
    groups.clear();
    PackingSink<N> sink(static_cast<int>(starts[static_cast<std::size_t>(t)]), packed, bodies,
                        inertia_in_plane_, unconstrained, dt, groups);
    written.write(t, runs, sink);
    // the writer wrote what it counted, unless the sink stopped it
    assert(!sink.in_plane() ||
           static_cast<std::size_t>(sink.next()) == starts[static_cast<std::size_t>(t) + 1]);
    planar_in_run_[static_cast<std::size_t>(t)] = sink.in_plane();
    friction_own_in_run_[static_cast<std::size_t>(t)] = sink.friction_on_own_bodies();
  });
  for (int t = 0; t < runs; ++t) {
    if (planar_in_run_[static_cast<std::size_t>(t)] == 0) return false;
  }
  for (int t = 0; t < runs; ++t) {
    add_groups(groups_of_run_[t]);
    friction_on_own_bodies_ = friction_on_own_bodies_ && friction_own_in_run_[t] != 0;
  }
  return true;
}

void Mlcp::assemble(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                    const std::vector<Vec6>& unconstrained, double dt, Workers* workers) {
  NoRows none;
  assemble(bodies, none, rows, unconstrained, dt, workers);
}

void Mlcp::assemble(const std::vector<RigidBody>& bodies, RowWriter& written,
                    const std::vector<ConstraintRow>& rows, const std::vector<Vec6>& unconstrained,
                    double dt, Workers* workers) {
  const int runs = runs_on(workers);
  const RunStarts starts = run_starts(workers, [&](int t) { return written.count(t, runs); });
  const std::size_t first = starts[static_cast<std::size_t>(runs)];  // the first of `rows`
  written.begin(first);
  // the layout: planar when every row and every body's I⁻¹ keep to the plane (each run of the
  // workers checks its bodies, then its share of `rows`; the written rows as they are packed)
  inertia_in_plane_.resize(bodies.size());
  planar_in_run_.assign(static_cast<std::size_t>(runs), 1);
  const auto check_bodies = [&](int t) {
    const auto [first_body, last_body] = share_of(bodies.size(), t, runs);
    for (size_t b = first_body; b < last_body; ++b) {
      inertia_in_plane_[b] = inertia_in_plane(bodies[b]);
    }
  };
  const auto check_rows = [&](int t) {
    const auto [begin, end] = share_of(rows.size(), t, runs);
    planar_in_run_[t] = std::all_of(
        rows.begin() + begin, rows.begin() + end,
        [&](const ConstraintRow& row) { return row_in_plane(row, inertia_in_plane_); });
  };
  run_on(workers, check_bodies);
  if (!rows.empty()) run_on(workers, check_rows);
  planar_ = std::all_of(planar_in_run_.begin(), planar_in_run_.end(),
                        [](unsigned char p) { return p != 0; });
  body_count_ = static_cast<int>(bodies.size());
  groups_.clear();
  friction_on_own_bodies_ = true;
  const std::size_t total = first + rows.size();
  if (planar_) {
    planar_rows_.resize(total);
    planar_ = pack_written(planar_rows_, bodies, written, starts, unconstrained, dt, workers);
  }
  if (!planar_) {
    general_rows_.resize(total);
    pack_written(general_rows_, bodies, written, starts, unconstrained, dt, workers);
  }
  visit_mutable([&](auto& packed) {
    pack_in_runs(first, rows.size(), workers, [&](std::size_t i, std::vector<RowGroup>& groups) {
      const ConstraintRow& row = rows[i - first];
      pack_row(bodies, row, unconstrained, dt, packed[i]);
      // the groups and the friction rows' bodies, from the rows as written (read-only: a row
      // of another run may not be packed yet) or as packed before them
      if (i == first || !same_bodies(row.Jmap, rows[i - first - 1].Jmap)) {
        groups.push_back({static_cast<int>(i), row.Jmap});
      }
      return on_own_bodies(row.Jmap, row.friction_of, row.friction_count, i, [&](int k) {
        const std::size_t at = static_cast<std::size_t>(k);
        return at >= first ? rows[at - first].Jmap : packed[at].map;
      });
    });
  });
  groups_.push_back({static_cast<int>(total), {-1, -1}});
}

template <class Finish>
void Mlcp::select_rows(const Mlcp& from, const std::vector<int>& rows, Workers* workers,
                       Finish&& finish) {
  planar_ = from.planar_;
  body_count_ = from.body_count_;
  groups_.clear();
  friction_on_own_bodies_ = true;
  auto select = [&](const auto& source, auto& packed) {
    packed.resize(rows.size());
    pack_in_runs(0, rows.size(), workers, [&](std::size_t i, std::vector<RowGroup>& groups) {
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
  groups_.push_back({static_cast<int>(rows.size()), {-1, -1}});
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


Mlcp assemble_mlcp(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                   double dt) {
  std::vector<Vec6> unconstrained;
  unconstrained_velocities(bodies, dt, unconstrained);
  Mlcp mlcp;
  mlcp.assemble(bodies, rows, unconstrained, dt);
  return mlcp;
}

}  // namespace lamina
