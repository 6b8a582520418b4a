#include "constraints/pgs_solver.h"

#include <algorithm>
#include <cassert>

namespace lamina {
namespace {

// Writes a row and its terms into a packed row of layout N, every field: packed rows keep their
// memory from step to step, and are written in place rather than copied in.
template <int N>
void pack(const ConstraintRow& row, const RowTerms<N>& terms, SweepRow<N>& packed) {
  assert(row.Jmap[0] != row.Jmap[1]);  // a row's two blocks are on two bodies
  // A row moves a body, so d_i = J_i M⁻¹ J_iᵀ > 0 and 1/d_i is finite. A row on static bodies
  // alone would give 0 · ∞ = NaN in the sweep; the World refuses such joints (add_joint) and
  // skips pairs of static bodies.
  assert(terms.d > 0.0);
  packed.map = row.Jmap;
  packed.eta = terms.eta;
  packed.inverse_d = 1.0 / terms.d;
  packed.lambda_min = row.lambda_min;
  packed.lambda_max = row.lambda_max;
  packed.friction_of = row.friction_of;
  packed.mu = row.mu;
  packed.J = terms.J;
  packed.B = terms.B;
}

// Whether a body's I⁻¹ turns the z axis into itself, so that B = M⁻¹ Jᵀ of a row in the plane
// (J's v_z, ω_x, ω_y zero) lies in the plane too.
bool inertia_in_plane(const RigidBody& body) {
  return body.inverse_inertia_world(0, 2) == 0.0 && body.inverse_inertia_world(1, 2) == 0.0;
}

template <int N>
void assemble_rows(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                   const std::vector<Vec6>& unconstrained, double dt, SweepRows<N>& packed) {
  packed.rows.resize(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    pack(rows[i], assemble_row<N>(bodies, rows[i], unconstrained, dt), packed.rows[i]);
  }
}

// An assembled MLCP's rows in layout N.
template <int N>
void load_rows(const Mlcp& mlcp, SweepRows<N>& packed) {
  packed.rows.resize(mlcp.rows.size());
  for (size_t i = 0; i < mlcp.rows.size(); ++i) {
    RowTerms<N> terms;
    for (int k = 0; k < 2; ++k) {
      terms.J[k] = cut<N>(mlcp.rows[i].Jsp[k]);
      terms.B[k] = cut<N>(mlcp.Bsp[i][k]);
    }
    terms.eta = mlcp.eta[static_cast<Eigen::Index>(i)];
    terms.d = mlcp.d[static_cast<Eigen::Index>(i)];
    pack(mlcp.rows[i], terms, packed.rows[i]);
  }
}

template <int N>
void copy_selected(const SweepRows<N>& from, const std::vector<int>& rows,
                   const std::vector<double>& eta, SweepRows<N>& to) {
  to.rows.resize(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    to.rows[i] = from.rows[rows[i]];
    to.rows[i].eta = eta[i];
  }
}

// a = B λ: the text's TransposeMultiply, scaled by λ[i] (the text writes λ[b1], λ[b2]).
template <int N>
void transpose_multiply(SweepRows<N>& s, int body_count, const double* lambda) {
  s.a.assign(static_cast<size_t>(body_count), Block<N>::Zero());
  for (size_t i = 0; i < s.rows.size(); ++i) {
    if (lambda[i] == 0.0) continue;  // adds nothing (a split-impulse solve starts from λ = 0)
    const SweepRow<N>& row = s.rows[i];
    s.a[row.map[0]] += lambda[i] * row.B[0];
    if (row.map[1] >= 0) s.a[row.map[1]] += lambda[i] * row.B[1];
  }
}

// Row i of a sweep, on the a_b of its two bodies (a2 unused for a one-body row).
template <int N>
void solve_row(const SweepRow<N>& row, size_t i, double* lambda, Block<N>& a1, Block<N>& a2) {
  const bool two_bodies = row.map[1] >= 0;
  double j_a = ordered_dot<N>(row.J[0], a1);
  if (two_bodies) j_a += ordered_dot<N>(row.J[1], a2);
  // Delta = (η_i − J_i · a) / d_i, Gauss-Seidel's (b_i − Σ_j A_ij λ_j) / A_ii; 1/d_i is
  // computed once per row when the row is packed, so the sweep multiplies instead of dividing
  const double delta = (row.eta - j_a) * row.inverse_d;
  const double old = lambda[i];
  const auto [lo, hi] = bounds_of(row, lambda);
  lambda[i] = std::max(lo, std::min(old + delta, hi));
  const double diff = lambda[i] - old;
  a1 += diff * row.B[0];
  if (two_bodies) a2 += diff * row.B[1];
}

// One Gauss-Seidel sweep over the rows, each λ_i projected onto its bounds. Consecutive rows on
// the same bodies (a pair's contact rows and their friction rows) keep their bodies' a_b in
// local variables: the same arithmetic, without a trip through memory per row.
template <int N>
void sweep_rows(SweepRows<N>& s, double* lambda) {
  const SweepRow<N>* rows = s.rows.data();
  Block<N>* a = s.a.data();
  const size_t count = s.rows.size();
  for (size_t i = 0; i < count;) {
    const int b1 = rows[i].map[0];
    const int b2 = rows[i].map[1];
    Block<N> a1 = a[b1];
    Block<N> a2 = b2 >= 0 ? a[b2] : Block<N>::Zero();
    for (; i < count && rows[i].map[0] == b1 && rows[i].map[1] == b2; ++i) {
      solve_row(rows[i], i, lambda, a1, a2);
    }
    a[b1] = a1;
    if (b2 >= 0) a[b2] = a2;
  }
}

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

template <int N>
void add_forces(const SweepRows<N>& s, const double* lambda, std::vector<RigidBody>& bodies) {
  for (size_t i = 0; i < s.rows.size(); ++i) {
    const SweepRow<N>& row = s.rows[i];
    // eq. 3-11: F_c = Jᵀ λ
    add_wrench(bodies[row.map[0]], lambda[i], row.J[0]);
    if (row.map[1] >= 0) add_wrench(bodies[row.map[1]], lambda[i], row.J[1]);
  }
}

}  // namespace

void PgsWorkspace::reset(int body_count, bool planar) {
  planar_ = planar;
  body_count_ = body_count;
}

void PgsWorkspace::load(const Mlcp& mlcp) {
  const bool planar = std::all_of(mlcp.Bsp.begin(), mlcp.Bsp.end(), [](const auto& B) {
    return in_plane(B[0]) && in_plane(B[1]);
  }) && std::all_of(mlcp.rows.begin(), mlcp.rows.end(), [](const ConstraintRow& row) {
    return in_plane(row.Jsp[0]) && in_plane(row.Jsp[1]);
  });
  reset(mlcp.body_count, planar);
  visit([&](auto& packed) { load_rows(mlcp, packed); });
}

void PgsWorkspace::assemble(const std::vector<RigidBody>& bodies,
                            const std::vector<ConstraintRow>& rows,
                            const std::vector<Vec6>& unconstrained, double dt) {
  inertia_in_plane_.resize(bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) inertia_in_plane_[b] = inertia_in_plane(bodies[b]);
  const bool planar = std::all_of(rows.begin(), rows.end(), [&](const ConstraintRow& row) {
    return in_plane(row.Jsp[0]) && in_plane(row.Jsp[1]) && inertia_in_plane_[row.Jmap[0]] &&
           (row.is_one_body() || inertia_in_plane_[row.Jmap[1]]);
  });
  reset(static_cast<int>(bodies.size()), planar);
  visit([&](auto& packed) { assemble_rows(bodies, rows, unconstrained, dt, packed); });
}

void PgsWorkspace::copy_rows(const PgsWorkspace& from, const std::vector<int>& rows,
                             const std::vector<double>& eta) {
  reset(from.body_count_, from.planar_);
  if (planar_) {
    copy_selected(from.planar_rows_, rows, eta, planar_rows_);
  } else {
    copy_selected(from.general_rows_, rows, eta, general_rows_);
  }
}

void PgsWorkspace::start(const double* lambda) {
  visit([&](auto& packed) { transpose_multiply(packed, body_count_, lambda); });
}

void PgsWorkspace::sweep(double* lambda) {
  visit([&](auto& packed) { sweep_rows(packed, lambda); });
}

void PgsWorkspace::solve(double* lambda, const PgsSettings& settings, const Mlcp* mlcp,
                         PgsResult& result) {
  assert(mlcp != nullptr || (!settings.record_residuals && settings.tolerance <= 0.0));
  start(lambda);
  const Eigen::Map<const Eigen::VectorXd> lambda_view(lambda, row_count());
  run_sweeps(
      settings, [&] { sweep(lambda); }, [&] { return mlcp_residual(*mlcp, lambda_view); }, result);
}

void PgsWorkspace::add_constraint_forces(std::vector<RigidBody>& bodies,
                                         const double* lambda) const {
  visit([&](const auto& packed) { add_forces(packed, lambda, bodies); });
}

int PgsWorkspace::row_count() const {
  return visit([](const auto& packed) { return static_cast<int>(packed.rows.size()); });
}

Vec6 PgsWorkspace::velocity_change(int body) const {
  return visit([&](const auto& packed) { return widen(packed.a[body]); });
}

PgsResult solve_pgs(const Mlcp& mlcp, const Eigen::VectorXd& lambda_exp, const PgsSettings& settings) {
  PgsWorkspace workspace;
  workspace.load(mlcp);
  PgsResult result;
  result.lambda = lambda_exp;
  workspace.solve(result.lambda.data(), settings, &mlcp, result);
  return result;
}

}  // namespace lamina
