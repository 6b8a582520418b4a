// The mixed linear complementarity problem of one step (eq. 3-16, 3-23, 3-24), assembled once:
//   J B λ = η  with  B = M⁻¹ Jᵀ,  η = ζ/Δt − J (V/Δt + M⁻¹ F_ext),  λ⁻ ≤ λ ≤ λ⁺.
//
// Mlcp holds the rows packed for the sweep (packed_rows.h), in the planar layout when every row
// and body lies in the plane and in the general one otherwise; both give the same numbers bit
// for bit (block_layout.h). It is the only assembled form. The text's form of the problem —
// Jsp, Bsp, Jmap, ζ, η, d, the bounds, W, the dense J and J M⁻¹ Jᵀ (dense_system.h) — is read
// from it through the views below; reports and explanations show those views.
//
// λ is kept by the caller (a World keeps its memory from step to step) and passed as a pointer
// to row_count() values.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "constraints/constraint_row.h"
#include "constraints/packed_rows.h"
#include "motion/rigid_body.h"
#include "parallel/workers.h"

namespace lamina {

// Body b's 6-vector [v; ω] (eq. 3-5) and [F; τ] of the forces accumulated on it (eq. 3-9;
// inline: PGS's last sweep reads it per group, add_group_forces).
Vec6 velocity_of(const RigidBody& body);
inline Vec6 external_force_of(const RigidBody& body) {
  Vec6 f;
  f.head<3>() = body.force;
  f.tail<3>() = body.torque;
  return f;
}

// M⁻¹ X for one body's 6-vector X: [m⁻¹ X_v; I⁻¹ X_ω] (eq. 3-12, the text's Convert).
Vec6 inverse_mass_times(const RigidBody& body, const Vec6& block);

// V/Δt + M⁻¹ F_ext of every body (eq. 3-16): the velocity each body would reach without
// constraints, per Δt, in m/s² or rad/s². `out` is resized to the bodies (its memory is reused).
// With `workers`, each of their threads takes a run of the bodies.
void unconstrained_velocities(const std::vector<RigidBody>& bodies, double dt,
                              std::vector<Vec6>& out, Workers* workers = nullptr);

// J_i V for a written row and the bodies' velocities now (eq. 5-4, 5-5: a contact point's
// velocity along n), summed as every J X of the MLCP is (row_dot).
double row_velocity(const ConstraintRow& row, const std::vector<RigidBody>& bodies);

// A run of consecutive rows on the same bodies: a contact pair's contact and friction rows, a
// joint's rows. A sweep keeps the run's a_b in registers (pgs_solver.h).
struct RowGroup {
  int first = 0;                  // its first row
  std::array<int, 2> bodies{-1, -1};  // Jmap of its rows
};

// Whether two rows or groups are on the same bodies, in the same order (compared element by
// element: std::array's == becomes a call to memcmp, a tenth of the packing's instructions and
// two thirds of a plan's, PartPlan::serves). Inlined: met once per row or group.
inline bool same_bodies(const std::array<int, 2>& a, const std::array<int, 2>& b) {
  return a[0] == b[0] && a[1] == b[1];
}

// Where rows go as they are written: a vector of ConstraintRows (the text's form), or an MLCP
// being assembled, which packs each row as it comes (Mlcp::assemble with a RowWriter) so that
// a step's many contact rows are never stored twice.
class RowSink {
 public:
  virtual ~RowSink() = default;
  // Takes `count` rows, in order: they become rows next() … next() + count − 1. False: the sink
  // takes no more rows (an MLCP packing in the planar layout was put a row out of the plane),
  // and the writer stops writing this run.
  virtual bool put(const ConstraintRow* rows, int count) = 0;
  int next() const { return next_; }  // the index the next row put gets

 protected:
  explicit RowSink(int first) : next_(first) {}
  int next_;
};

// Rows written in runs, straight into a sink: run t of `runs` writes its rows after those of
// the runs before it. count(t, runs) and then write(t, runs, sink) are called on run t's thread
// (a team's, or the calling thread for one run), begin(total) once between, on the calling
// thread. write stops a run where its sink's put returns false, and may be called again for all
// the runs (an MLCP that finds a row out of the plane stops the writing and has the rows written
// again, to pack them in the general layout): it writes the same rows again.
class RowWriter {
 public:
  virtual ~RowWriter() = default;
  virtual std::size_t count(int t, int runs) = 0;  // how many rows run t writes
  virtual void begin(std::size_t total) = 0;         // all the runs' rows: `total`
  virtual void write(int t, int runs, RowSink& sink) = 0;
};

class Mlcp {
 public:
  // Assembles the MLCP of eq. 3-16 for the rows, `unconstrained` being each body's
  // V/Δt + M⁻¹ F_ext (unconstrained_velocities; zeros: η = ζ/Δt). Its memory is reused. With
  // `workers`, each of their threads packs a run of the rows (each row's numbers are its own).
  void assemble(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                const std::vector<Vec6>& unconstrained, double dt, Workers* workers = nullptr);
  // The same for the rows `written` writes, packed as it writes them (with `workers`, each of
  // their threads writes and packs a run of them), then `rows`: the MLCP of the rows of both,
  // in that order, as the first assemble would make it of them in one vector.
  void assemble(const std::vector<RigidBody>& bodies, RowWriter& written,
                const std::vector<ConstraintRow>& rows, const std::vector<Vec6>& unconstrained,
                double dt, Workers* workers = nullptr);
  // Some rows of another MLCP on the same bodies, each asking a new ζ of bodies that start from
  // rest under no force: rows[i] of `from` becomes row i with ζ_i = zeta[i], η_i = ζ_i / Δt
  // (split impulse's position rows are the velocity MLCP's contact rows: J, B, d and the bounds
  // are the same).
  void assemble_rows_of(const Mlcp& from, const std::vector<int>& rows,
                        const std::vector<double>& zeta, double dt, Workers* workers = nullptr);

  // Rows of another MLCP as an MLCP of their own, η and all unchanged (an island of it, whose rows
  // touch no body that other rows touch, is solved apart: eq. 3-24 splits). `rows` ascend; the
  // bodies keep their indices; a friction row's contact rows must be among `rows`, consecutive as
  // they were, and are renumbered.
  void assemble_subset(const Mlcp& from, const std::vector<int>& rows, Workers* workers = nullptr);

  int row_count() const;
  int body_count() const { return body_count_; }  // n, the bodies V spans
  // The rows in runs on the same bodies, as assembled: group g is rows [groups()[g].first,
  // groups()[g + 1].first); a last entry, past the groups, has first = row_count().
  const std::vector<RowGroup>& groups() const { return groups_; }
  // Whether every friction row's contact rows lie before it on its own bodies (a contact's
  // always do): then an order kept per body orders the friction bounds too.
  bool friction_on_own_bodies() const { return friction_on_own_bodies_; }

  // The text's form of row i: as a ConstraintRow, and its parts one by one.
  ConstraintRow row(int i) const;             // Jsp, Jmap, ζ, the bounds and friction
  std::array<int, 2> bodies_of(int i) const;  // Jmap: body indices, [1] = −1 for a one-body row
  Vec6 jacobian(int i, int k) const;          // Jsp[i][k], [v ω]; zero for a missing body
  Vec6 b_block(int i, int k) const;           // Bsp[i][k] = M⁻¹ J_iᵀ's block (Convert)
  double zeta(int i) const;                   // ζ_i, in m/s or rad/s (eq. 3-15)
  double eta(int i) const;                    // η_i, in m/s² or rad/s² (eq. 3-16)
  double d(int i) const;                      // d_i = J_i · B_i, the diagonal of J B
  // the (first) contact row bounding a friction row, or −1
  int friction_of(int i) const;
  int friction_count(int i) const;            // how many contact rows from friction_of bound it
  double mu(int i) const;                     // μ of a friction row (its bounds: ±μ Σ λc)
  // λ⁻_i and λ⁺_i for the current λ: fixed, or ±μ λc for a friction row (eq. 3-26).
  std::array<double, 2> bounds(int i, const double* lambda) const;

  // W = J B λ − η (eq. 3-23).
  Eigen::VectorXd slack(const double* lambda) const;
  // How far λ is from solving the MLCP: per row |W_i| when λ is inside its bounds, and only the
  // wrong-signed part of W_i at a bound (eq. 3-24); the Euclidean norm over rows.
  double residual(const double* lambda) const;
  // J_i X for per-body 6-vectors X (e.g. V: J_i V, eq. 3-8).
  double row_times(int i, const std::vector<Vec6>& per_body) const;

  // F_c = Jᵀ λ (eq. 3-11) added to each body's accumulated force and torque. With `workers`,
  // each of their threads adds to a run of the bodies (each body's sum in row order all the same).
  // PGS can add it in its last sweep instead (PgsSolver::solve's `forces_to`), the same sums.
  void add_constraint_forces(std::vector<RigidBody>& bodies, const double* lambda,
                             Workers* workers = nullptr) const;
  // Body b's share of F_c = Jᵀ λ, [f_c; τ_c] about its centre, in N and N·m (eq. 3-11, 5-9).
  Vec6 constraint_wrench(int body, const double* lambda) const;

  // f(rows) on the packed rows of the layout in use (PackedRows<3> or PackedRows<6>).
  template <class F>
  decltype(auto) visit(F&& f) const {
    return planar_ ? f(planar_rows_) : f(general_rows_);
  }

 private:
  template <class F>
  decltype(auto) visit_mutable(F&& f) {
    return planar_ ? f(planar_rows_) : f(general_rows_);
  }
  // Packs rows first .. first + count − 1 by pack(i, groups), in runs on the workers' threads
  // (or one run), each run noting the groups that start in it; pack returns whether a friction
  // row i has its contact rows before it on its own bodies. Then adds the runs' groups in order
  // (add_groups).
  template <class Pack>
  void pack_in_runs(std::size_t first, std::size_t count, Workers* workers, Pack&& pack);
  // The rows `written` writes, packed in the layout of N as they are written, in runs; false
  // when one of them does not lie in the plane that N = 3 asks for.
  template <int N>
  bool pack_written(PackedRows<N>& packed, const std::vector<RigidBody>& bodies,
                    RowWriter& written, const RunStarts& starts,
                    const std::vector<Vec6>& unconstrained, double dt, Workers* workers);
  // Adds a run's groups to groups_ in order: its first group joins the last one added when both
  // are on the same bodies (a run that starts amid a run of rows on the same bodies).
  void add_groups(const std::vector<RowGroup>& groups);
  // Rows of `from` copied as rows 0 .. rows.size() − 1 (assemble_subset), each then handed to
  // finish(row, i) while it is at hand (assemble_rows_of sets its ζ and η).
  template <class Finish>
  void select_rows(const Mlcp& from, const std::vector<int>& rows, Workers* workers,
                   Finish&& finish);

  bool planar_ = true;           // the layout in use: planar_rows_ or general_rows_
  int body_count_ = 0;           // n
  PackedRows<3> planar_rows_;    // [v_x v_y ω_z] blocks
  PackedRows<6> general_rows_;   // [v ω] blocks
  std::vector<unsigned char> inertia_in_plane_;  // per body: I⁻¹ turns z into z (scratch)
  std::vector<RowGroup> groups_;           // runs of rows on the same bodies, and an end
  bool friction_on_own_bodies_ = true;
  PerRun<std::vector<RowGroup>> groups_of_run_;  // scratch of pack_in_runs
  std::vector<unsigned char> friction_own_in_run_;
  std::vector<unsigned char> planar_in_run_;  // scratch of assemble
};

// Body b's accumulated force and torque set from a block in the layout of N, [f; τ] or
// [f_x f_y τ_z] (in the plane the other three components left as they are): the inverse of
// cut<N>(external_force_of(body)).
template <int N>
void set_wrench_block(RigidBody& body, const Block<N>& w) {
  if constexpr (N == 3) {
    body.force.x() = w[0];
    body.force.y() = w[1];
    body.torque.z() = w[2];
  } else {
    body.force = w.template head<3>();
    body.torque = w.template tail<3>();
  }
}

// The terms of F_c = Jᵀ λ (eq. 3-11) of rows [first, last) of one group (Mlcp::groups: rows on
// the same bodies) added to its bodies' forces and torques, to each body whose `to` entry is
// set: row by row in row order, each body's sum held over the group instead of stored after
// every row (the same additions in the same order: the same bits).
template <int N>
void add_group_forces(const PackedRow<N>* rows, const double* lambda, int first, int last,
                      RigidBody* bodies, std::array<bool, 2> to = {true, true}) {
  const std::array<int, 2> map = rows[first].map;
  to[1] = to[1] && map[1] >= 0;
  // (a body not to be added to sums from zero, and is left alone)
  Block<N> f1 = to[0] ? cut<N>(external_force_of(bodies[map[0]])) : Block<N>::Zero();
  Block<N> f2 = to[1] ? cut<N>(external_force_of(bodies[map[1]])) : Block<N>::Zero();
  for (int i = first; i < last; ++i) add_force_term(rows[i], lambda[i], f1, f2);
  if (to[0]) set_wrench_block<N>(bodies[map[0]], f1);
  if (to[1]) set_wrench_block<N>(bodies[map[1]], f2);
}

// The MLCP of the rows for the bodies' velocities and accumulated forces now (eq. 3-16).
Mlcp assemble_mlcp(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                   double dt);

}  // namespace lamina
