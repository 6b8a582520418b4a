// Gauss-Seidel and Projected Gauss-Seidel against exact answers (chapter 3, eq. 3-16..3-26).
#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <random>
#include <sstream>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "constraints/constrained_step.h"
#include "constraints/dense_system.h"
#include "constraints/gauss_seidel.h"
#include "constraints/jacobian_rows.h"
#include "constraints/mlcp.h"
#include "constraints/pgs_solver.h"
#include "constraints/revolute_joint.h"
#include "support/random_systems.h"

using namespace lamina;

namespace {

constexpr double dt = random_system_dt;  // Δt of every system here, in s

double condition_number(const Eigen::MatrixXd& A) {
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
  return ev.maxCoeff() / ev.minCoeff();
}

// The fixed bounds λ⁻ (side 0) or λ⁺ (side 1) of every row (these systems have no friction rows,
// whose bounds would follow λ).
Eigen::VectorXd fixed_bounds(const Mlcp& mlcp, int side) {
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(mlcp.row_count());
  Eigen::VectorXd bound(mlcp.row_count());
  for (int i = 0; i < mlcp.row_count(); ++i) bound[i] = mlcp.bounds(i, lambda.data())[side];
  return bound;
}

// Every condition of eq. 3-24 for W = A λ − η, to tolerance tol (absolute, on λ and on W).
bool satisfies_eq_3_24(const Eigen::MatrixXd& A, const Eigen::VectorXd& eta,
                       const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                       const Eigen::VectorXd& lambda, double tol) {
  const Eigen::VectorXd W = A * lambda - eta;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    const bool at_lower = std::abs(lambda[i] - lo[i]) <= tol;
    const bool at_upper = std::abs(lambda[i] - hi[i]) <= tol;
    if (lambda[i] < lo[i] - tol || lambda[i] > hi[i] + tol) return false;  // λ⁻ ≤ λ ≤ λ⁺
    if (!at_lower && !at_upper && std::abs(W[i]) > tol) return false;      // inside → W = 0
    if (at_lower && !at_upper && W[i] < -tol) return false;                // at λ⁻ → W ≥ 0
    if (at_upper && !at_lower && W[i] > tol) return false;                 // at λ⁺ → W ≤ 0
  }
  return true;
}

// The MLCP by enumeration: each row is put at λ⁻, at λ⁺ or free (3^s assignments); rows at a
// bound are fixed there, the free rows solve their part of A λ = η exactly (LDLT), and the
// first assignment whose λ satisfies eq. 3-24 is returned. For positive definite A the MLCP
// has exactly one solution (the minimum of a strictly convex quadratic over a box).
std::optional<Eigen::VectorXd> brute_force_mlcp(const Eigen::MatrixXd& A,
                                                const Eigen::VectorXd& eta,
                                                const Eigen::VectorXd& lo,
                                                const Eigen::VectorXd& hi) {
  const auto s = static_cast<int>(eta.size());
  const int assignments = static_cast<int>(std::pow(3, s));
  for (int code = 0; code < assignments; ++code) {
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(s);
    std::vector<int> free_rows;
    bool possible = true;
    for (int i = 0, c = code; i < s; ++i, c /= 3) {
      const double bound = c % 3 == 0 ? lo[i] : hi[i];
      if (c % 3 == 2) free_rows.push_back(i);
      else if (std::isfinite(bound)) lambda[i] = bound;
      else possible = false;
    }
    if (!possible) continue;
    const auto f = static_cast<Eigen::Index>(free_rows.size());
    Eigen::MatrixXd A_ff(f, f);
    Eigen::VectorXd rhs(f);
    for (Eigen::Index r = 0; r < f; ++r) {
      // A_FF λ_F = η_F − A_F,fixed λ_fixed (λ_F is still 0 in lambda)
      rhs[r] = eta[free_rows[r]] - A.row(free_rows[r]).dot(lambda);
      for (Eigen::Index c = 0; c < f; ++c) A_ff(r, c) = A(free_rows[r], free_rows[c]);
    }
    const Eigen::VectorXd lambda_f = A_ff.ldlt().solve(rhs);
    for (Eigen::Index r = 0; r < f; ++r) lambda[free_rows[r]] = lambda_f[r];
    if (satisfies_eq_3_24(A, eta, lo, hi, lambda, 1e-9)) return lambda;
  }
  return std::nullopt;
}

// A chain of boxes 0.5 m × 0.1 m, 1 kg each, laid out straight from the origin at the given
// angle from +x: link 0 pinned to the world at the origin, each next link pinned to the one
// before at their shared end.
ConstraintList straight_chain(std::vector<RigidBody>& bodies, int links, double angle) {
  const Vec3 along(std::cos(angle), std::sin(angle), 0.0);
  ConstraintList joints;
  for (int k = 0; k < links; ++k) {
    bodies.push_back(box_body(20.0, 0.25, 0.05, (0.5 * k + 0.25) * along, angle));
    const Vec3 pivot = 0.5 * k * along;
    joints.push_back(std::make_unique<RevoluteJoint>(anchor_at(bodies, k == 0 ? world : k - 1, pivot),
                                                     anchor_at(bodies, k, pivot)));
  }
  return joints;
}

std::string join(const std::vector<double>& values) {
  std::ostringstream out;
  out.precision(3);
  for (double v : values) out << " " << v;
  return out.str();
}

}  // namespace

TEST_SUITE("PgsSolver") {
  TEST_CASE("Gauss-Seidel converges to the LDLT solution of a positive definite system") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
      const int s = 8;
      // A = X Xᵀ / s + E: symmetric positive definite, eigenvalues in [1, ~4]
      const Eigen::MatrixXd X = random_matrix(rng, s, s, 1.0);
      const Eigen::MatrixXd A = X * X.transpose() / s + Eigen::MatrixXd::Identity(s, s);
      const Eigen::VectorXd b = random_matrix(rng, s, 1, 10.0);
      const Eigen::VectorXd exact = A.ldlt().solve(b);
      // up to 200 sweeps, stopping at ‖A λ − b‖ ≤ 1e-12 (b ~ 10); measured: at most 17 sweeps
      const SweepResult gs = gauss_seidel(A, b, Eigen::VectorXd::Zero(s), {200, 1e-12, false});
      CHECK(gs.iterations < 200);
      // ‖λ − λ_exact‖ ≤ ‖A⁻¹‖ ‖A λ − b‖ ≤ 1e-12 since A's eigenvalues are ≥ 1
      CHECK((gs.lambda - exact).norm() <= 1e-12);
    }
  }

  TEST_CASE("PGS with unbounded rows is Gauss-Seidel on J B λ = η, sweep for sweep") {
    std::mt19937 rng(11);
    const RandomSystem sys = random_system(rng, 3, 6, false);
    for (int sweeps = 1; sweeps <= 5; ++sweeps) {
      const SweepSettings settings{sweeps, 0.0, false};
      const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
      const SweepResult pgs = solve_pgs(sys.mlcp, zero, settings);
      const SweepResult gs = gauss_seidel(sys.dense.JB, sys.dense.eta, zero, settings);
      // the text: PGS's Delta is Gauss-Seidel's Delta; equal up to rounding (1e-12 relative)
      CHECK((pgs.lambda - gs.lambda).norm() <= 1e-12 * (1.0 + gs.lambda.norm()));
    }
  }

  TEST_CASE("PGS converges to the LDLT solution of random equality systems J B λ = η") {
    std::mt19937 rng(3);
    for (int trial = 0; trial < 20; ++trial) {
      const RandomSystem sys = random_system(rng, 3, 6, false);
      // well conditioned: 6 random rows on 18 velocities; checked, not assumed (measured ≤ 81)
      REQUIRE(condition_number(sys.dense.JB) < 100.0);
      const Eigen::VectorXd exact = sys.dense.JB.ldlt().solve(sys.dense.eta);
      // up to 2000 sweeps, stopping once the MLCP residual ‖W‖ ≤ 1e-10 (η ~ 60 m/s²);
      // measured: at most 266 sweeps
      const SweepResult pgs = solve_pgs(sys.mlcp, Eigen::VectorXd::Zero(6), {2000, 1e-10, false});
      CHECK(pgs.iterations < 2000);
      // ‖λ − λ_exact‖ ≤ ‖(J B)⁻¹‖ ‖W‖; 1e-7 N leaves room for ‖(J B)⁻¹‖ up to 1e3 kg
      CHECK((pgs.lambda - exact).norm() <= 1e-7);
    }
  }

  TEST_CASE("PGS solves random boxed MLCPs: eq. 3-24 holds and brute force agrees") {
    std::mt19937 rng(5);
    for (int s = 1; s <= 6; ++s) {
      for (int trial = 0; trial < 10; ++trial) {
        const RandomSystem sys = random_system(rng, 3, s, true);
        REQUIRE(condition_number(sys.dense.JB) < 100.0);
        const Eigen::VectorXd lo = fixed_bounds(sys.mlcp, 0);
        const Eigen::VectorXd hi = fixed_bounds(sys.mlcp, 1);
        // stop at ‖W‖ ≤ 1e-10 (eq. 3-24 residual, mlcp.h); measured: at most 132 sweeps
        const SweepResult pgs = solve_pgs(sys.mlcp, Eigen::VectorXd::Zero(s), {2000, 1e-10, false});
        CHECK(pgs.iterations < 2000);
        // eq. 3-24 to 1e-8 (N for λ, m/s² for W): the solver stopped at ‖W‖ ≤ 1e-10
        CHECK(satisfies_eq_3_24(sys.dense.JB, sys.dense.eta, lo, hi, pgs.lambda, 1e-8));
        const std::optional<Eigen::VectorXd> exact = brute_force_mlcp(sys.dense.JB, sys.dense.eta, lo, hi);
        REQUIRE(exact.has_value());
        // the MLCP's one solution; 1e-7 N as for the equality systems (measured ≤ 3e-10 N)
        CHECK((pgs.lambda - *exact).norm() <= 1e-7);
      }
    }
  }

  TEST_CASE("PGS stops at the tolerance and records the residual of every sweep") {
    std::mt19937 rng(13);
    const RandomSystem sys = random_system(rng, 3, 6, true);
    const SweepResult pgs = solve_pgs(sys.mlcp, Eigen::VectorXd::Zero(6), {1000, 1e-6, true});
    REQUIRE(pgs.iterations < 1000);
    CHECK(pgs.residuals.size() == static_cast<size_t>(pgs.iterations));
    CHECK(pgs.residuals.back() <= 1e-6);
    CHECK(pgs.residuals[pgs.residuals.size() - 2] > 1e-6);
    // each recorded value is the MLCP's residual after that sweep (identity)
    CHECK(pgs.residuals.back() == sys.mlcp.residual(pgs.lambda.data()));
  }

  TEST_CASE("TransposeMultiply scales row i's B by λ[i], not by λ of its body index") {
    std::mt19937 rng(17);
    std::vector<RigidBody> bodies{random_body(rng), random_body(rng)};
    // row 0 acts on bodies 1 and 0, row 1 on body 0 alone: the text's λ[b1] would read λ[1]
    // for row 0, and λ[b2] = λ[0] for its second block
    ConstraintRow row0, row1;
    row0.Jsp = {random_vec6(rng), random_vec6(rng)};
    row0.Jmap = {1, 0};
    row1.Jsp = {random_vec6(rng), Vec6::Zero()};
    row1.Jmap = {0, world};
    const std::vector<ConstraintRow> rows{row0, row1};
    const Mlcp mlcp = assemble_mlcp(bodies, rows, dt);
    const Eigen::VectorXd lambda = Eigen::Vector2d(2.0, 5.0);
    // PGS's a = B λ_exp before its first sweep (0 sweeps: the text's TransposeMultiply alone)
    PgsSolver solver;
    Eigen::VectorXd solved = lambda;
    SweepResult result;
    solver.solve(mlcp, solved.data(), {0, 0.0, false}, result);
    const std::vector<Vec6> a{solver.velocity_change(0), solver.velocity_change(1)};
    // expected: a = B λ = M⁻¹ Jᵀ λ from the dense path (eq. 3-16)
    const DenseSystem dense = build_dense_system(bodies, rows, dt);
    const Eigen::VectorXd expected = dense.inverse_mass * dense.J.transpose() * lambda;
    CHECK((a[0] - expected.segment<6>(0)).norm() <= 1e-12 * expected.norm());
    CHECK((a[1] - expected.segment<6>(6)).norm() <= 1e-12 * expected.norm());
    // the text's version would give body 1 λ[1] Bsp[0][0] = 5 Bsp[0][0]: visibly different
    const Vec6 text_a1 = lambda[1] * mlcp.b_block(0, 0);
    CHECK((a[1] - text_a1).norm() > 0.1 * expected.norm());
    // The pitfall lambda-b1 puts the text's slip back: row 0 (bodies 1, 0) adds λ[1] Bsp[0][0] to
    // body 1 and λ[0] Bsp[0][1] to body 0; row 1 (body 0) adds λ[0] Bsp[1][0] to body 0.
    Pitfalls slip;
    slip.add(Pitfall::lambda_b1);
    PgsSolver text_solver;
    Eigen::VectorXd text_solved = lambda;
    text_solver.solve(mlcp, text_solved.data(), {0, 0.0, false}, result, slip);
    const Vec6 text_a0 = lambda[0] * (mlcp.b_block(0, 1) + mlcp.b_block(1, 0));
    CHECK((text_solver.velocity_change(1) - text_a1).norm() <= 1e-12 * text_a1.norm());
    CHECK((text_solver.velocity_change(0) - text_a0).norm() <= 1e-12 * text_a0.norm());
  }

  TEST_CASE("the record of λ after each sweep is what that many sweeps give, and changes nothing") {
    // the viewer's ↑/↓ show these records: sweep s must be PGS stopped after s sweeps from the
    // same λ_exp (an independent solve per s), bit for bit; recording must not change the answer
    std::vector<RigidBody> bodies;
    const ConstraintList joints = straight_chain(bodies, 4, -M_PI / 2 + 0.3);
    ConstrainedStepSettings settings;
    WarmStart warm_start;
    StepReport report;
    for (int step = 0; step < 5; ++step) constrained_step(bodies, joints, settings, warm_start, &report);
    const Eigen::VectorXd start = report.lambda_exp;
    const SweepResult recorded = solve_pgs(report.mlcp, start, {10, 0.0, true});
    REQUIRE(recorded.lambdas.size() == 10);
    REQUIRE(recorded.residuals.size() == 10);
    for (int s = 1; s <= 10; ++s) {
      CAPTURE(s);
      const SweepResult stopped = solve_pgs(report.mlcp, start, {s, 0.0, false});
      CHECK(stopped.lambdas.empty());  // nothing kept unless asked
      CHECK((recorded.lambdas[static_cast<std::size_t>(s - 1)] - stopped.lambda).cwiseAbs().maxCoeff() == 0.0);
      CHECK(recorded.residuals[static_cast<std::size_t>(s - 1)] == report.mlcp.residual(stopped.lambda.data()));
    }
    CHECK((recorded.lambda - solve_pgs(report.mlcp, start, {10, 0.0, false}).lambda).cwiseAbs().maxCoeff() == 0.0);
    // the sweeps change λ (else the record would prove nothing)
    CHECK((recorded.lambdas[0] - recorded.lambdas[9]).norm() > 0.0);
  }

  TEST_CASE("warm starting from last step's λ needs fewer sweeps on a swinging chain") {
    // a chain of 4 links released straight, 0.3 rad from hanging down, swinging for 1 s
    std::vector<RigidBody> bodies;
    const ConstraintList joints = straight_chain(bodies, 4, -M_PI / 2 + 0.3);
    ConstrainedStepSettings settings;
    settings.step.iterations = 1000;  // sweeps until ‖W‖ ≤ 1e-3 m/s² (1e-4 g)
    settings.tolerance = 1e-3;
    const SweepSettings sweeps{settings.step.iterations, settings.tolerance, false};
    WarmStart warm_start;
    int warm_total = 0;
    int cold_total = 0;
    for (int step = 0; step < 60; ++step) {
      StepReport report;
      constrained_step(bodies, joints, settings, warm_start, &report);
      const auto s = report.mlcp.row_count();
      const SweepResult cold = solve_pgs(report.mlcp, Eigen::VectorXd::Zero(s), sweeps);
      if (step == 0) continue;  // the first step has no last answer to start from
      // measured: from last step's λ every step needs strictly fewer sweeps than from zero
      CHECK(report.solution.iterations < cold.iterations);
      warm_total += report.solution.iterations;
      cold_total += cold.iterations;
      if (step == 30) {
        const SweepSettings ten{10, 0.0, true};
        MESSAGE("step 30, ‖W‖ (m/s²) per sweep from last λ:"
                << join(solve_pgs(report.mlcp, report.lambda_exp, ten).residuals));
        MESSAGE("step 30, ‖W‖ (m/s²) per sweep from zero:   "
                << join(solve_pgs(report.mlcp, Eigen::VectorXd::Zero(s), ten).residuals));
      }
    }
    MESSAGE("sweeps to ‖W‖ ≤ 1e-3 m/s², steps 1..59: warm " << warm_total << ", cold " << cold_total);
    // measured 1610 against 3928; asserted with margin as "less than half"
    CHECK(2 * warm_total < cold_total);
  }
}
