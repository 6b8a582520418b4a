// Projected Gauss-Seidel for the MLCP of eq. 3-24 (chapter 3, "Projected Gauss-Seidel Method").
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "constraints/mlcp.h"

namespace lamina {

struct PgsSettings {
  int iterations = 10;            // MAX_ITERATION of the text: sweeps over all rows
  double tolerance = 0.0;         // stop early once the MLCP residual is ≤ this; 0 runs every sweep
  bool record_residuals = false;  // keep the residual after every sweep (for plots and tests)
};

struct PgsResult {
  Eigen::VectorXd lambda;          // λ, in N (force) or N·m (torque); impulse is λ Δt
  int iterations = 0;              // sweeps run
  std::vector<double> residuals;   // the MLCP residual after each sweep, when recorded
};

// Runs sweep() up to settings.iterations times, counting them in result.iterations. After each
// sweep, when residuals are recorded or a tolerance is set, measures residual() (one double),
// records it if asked, and stops once it is ≤ a tolerance > 0. Recording alone never changes
// the sweeps run, so λ is the same bit for bit with or without it. Shared by Gauss-Seidel and PGS.
template <class Sweep, class Residual>
void run_sweeps(const PgsSettings& settings, Sweep&& sweep, Residual&& residual,
                PgsResult& result) {
  const bool measure = settings.record_residuals || settings.tolerance > 0.0;
  for (int iter = 0; iter < settings.iterations; ++iter) {
    sweep();
    result.iterations = iter + 1;
    if (!measure) continue;
    const double r = residual();
    if (settings.record_residuals) result.residuals.push_back(r);
    if (settings.tolerance > 0.0 && r <= settings.tolerance) break;
  }
}

// The rows of an MLCP as the sweep reads them, one struct per row, contiguous: the text's Jsp,
// Bsp (its Convert), Jmap, η_i, 1/d_i and bounds side by side, each block in the layout of N
// components (block_layout.h: all six, or [v_x v_y ω_z] in the plane).
struct SweepRowScalars {
  std::array<int, 2> map{-1, -1};  // Jmap: body indices, map[1] = −1 for a one-body row
  double eta = 0.0;                // η_i, in m/s² or rad/s² (eq. 3-16)
  double inverse_d = 0.0;          // 1/d_i, d_i = J_i · B_i
  double lambda_min = 0.0;         // λ⁻ of a row with fixed bounds, in N
  double lambda_max = 0.0;         // λ⁺ of a row with fixed bounds, in N
  int friction_of = -1;            // the contact row bounding a friction row, or −1
  double mu = 0.0;                 // μ of a friction row
};

template <int N>
struct SweepRow : SweepRowScalars {
  std::array<Block<N>, 2> J;  // J_i's blocks for map[0], map[1] (Jsp)
  std::array<Block<N>, 2> B;  // B_i's blocks, M⁻¹ J_iᵀ (Bsp)
};

// The packed rows of one layout, and a = B λ, one block per body (the text's a).
template <int N>
struct SweepRows {
  std::vector<SweepRow<N>> rows;  // the MLCP's rows, in row order
  std::vector<Block<N>> a;        // a = B λ, kept current through the sweeps
};

// PGS's working memory, kept from solve to solve so that a World step allocates nothing once its
// buffers have grown. It holds the MLCP packed for the sweep, in the planar layout when every
// row and body lies in the plane, in the general one otherwise; both give the same λ bit for
// bit (block_layout.h).
class PgsWorkspace {
 public:
  // Packs an assembled MLCP (its Bsp, η and d).
  void load(const Mlcp& mlcp);
  // Assembles the MLCP of eq. 3-16 for these rows straight into the packed form, `unconstrained`
  // being each body's V/Δt + M⁻¹ F_ext (assemble_row).
  void assemble(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                const std::vector<Vec6>& unconstrained, double dt);

  // Some rows of another workspace's MLCP, on the same bodies, with new η: rows[i] of `from`
  // becomes row i here, with η_i = eta[i] (split impulse's position rows are the velocity MLCP's
  // contact rows, J, B, d and bounds unchanged).
  void copy_rows(const PgsWorkspace& from, const std::vector<int>& rows,
                 const std::vector<double>& eta);

  // Starts from λ = λ_exp: a = B λ (the text's TransposeMultiply). λ has one entry per row.
  void start(const double* lambda);
  // One Gauss-Seidel sweep over the rows, each λ_i projected onto its bounds; λ updated in place.
  void sweep(double* lambda);
  // start, then up to settings.iterations sweeps on λ in place (λ holds λ_exp on entry), as
  // run_sweeps counts and stops them; result.iterations and result.residuals are filled,
  // result.lambda is left alone. `mlcp`, the assembled form of the rows, is read only to measure
  // the residual (when recorded or a tolerance is set); it may be null otherwise.
  void solve(double* lambda, const PgsSettings& settings, const Mlcp* mlcp, PgsResult& result);

  // F_c = Jᵀ λ (eq. 3-11) added to each body's accumulated force and torque, read from the
  // packed rows: apply_constraint_forces's numbers without its products with zero.
  void add_constraint_forces(std::vector<RigidBody>& bodies, const double* lambda) const;

  int row_count() const;
  // (B λ)_b for the λ of the last sweep: body b's velocity change per Δt from the rows, [v; ω].
  Vec6 velocity_change(int body) const;

 private:
  void reset(int body_count, bool planar);
  // f(rows), on the packed rows of the layout in use.
  template <class F>
  decltype(auto) visit(F&& f) {
    return planar_ ? f(planar_rows_) : f(general_rows_);
  }
  template <class F>
  decltype(auto) visit(F&& f) const {
    return planar_ ? f(planar_rows_) : f(general_rows_);
  }

  bool planar_ = true;         // the layout in use: planar_rows_ or general_rows_
  int body_count_ = 0;         // n, the bodies the rows act on
  SweepRows<3> planar_rows_;   // [v_x v_y ω_z] blocks
  SweepRows<6> general_rows_;  // [v ω] blocks
  std::vector<unsigned char> inertia_in_plane_;  // per body: I⁻¹ turns z into z (scratch)
};

// Solves J B λ = η within the rows' bounds, starting from the guess λ_exp (warm start).
// Follows the text's pseudo-code with its two faults mended: TransposeMultiply scales by λ[i]
// (the text writes λ[b1], λ[b2]), and a one-body row (Jmap[1] = −1) never reads a[−1].
// A friction row's bounds ±μ λc are read from its contact row's current λ (eq. 3-26).
// Runs in a PgsWorkspace of its own (see above); a caller solving every step keeps one instead.
PgsResult solve_pgs(const Mlcp& mlcp, const Eigen::VectorXd& lambda_exp, const PgsSettings& settings);

}  // namespace lamina
