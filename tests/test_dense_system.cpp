// The one assembled MLCP (mlcp.h) against the dense matrices of chapter 3 written out in full
// (dense_system.h): the MLCP's views of the text's form — J, Bᵀ, J B, η, d, W = J B λ − η and
// F_c = Jᵀ λ — equal the independent dense reference built from the same written rows by matrix
// products alone (eq. 3-8, 3-11, 3-12, 3-16, 3-23).
#include <doctest/doctest.h>

#include <random>
#include <type_traits>
#include <vector>

#include "constraints/constraint.h"
#include "constraints/dense_system.h"
#include "constraints/mlcp.h"
#include "support/constraint_scenes.h"
#include "support/random_systems.h"

using namespace lamina;

namespace {

// One of the MLCP's per-row views for every row: η_i (&Mlcp::eta) or d_i (&Mlcp::d).
Eigen::VectorXd per_row(const Mlcp& mlcp, double (Mlcp::*view)(int) const) {
  Eigen::VectorXd values(mlcp.row_count());
  for (int i = 0; i < mlcp.row_count(); ++i) values[i] = (mlcp.*view)(i);
  return values;
}

// The components per block of the layout the MLCP was assembled in: 3 planar, 6 general.
int block_size(const Mlcp& mlcp) {
  return mlcp.visit([](const auto& rows) { return std::decay_t<decltype(rows)>::value_type::size; });
}

}  // namespace

TEST_SUITE("DenseSystem") {
  TEST_CASE("the dense path agrees with the sparse one: η, diagonal d, Bᵀ, W and Jᵀ λ") {
    std::vector<RigidBody> bodies;
    const ConstraintList constraints = shaken_mixed_scene(bodies, 29);
    const double dt = 1.0 / 60.0;
    const std::vector<ConstraintRow> rows = write_all_rows(bodies, constraints, dt, 0.2);
    const Mlcp mlcp = assemble_mlcp(bodies, rows, dt);
    const DenseSystem dense = build_dense_system(bodies, rows, dt);
    const Eigen::VectorXd eta = per_row(mlcp, &Mlcp::eta);
    const Eigen::VectorXd d = per_row(mlcp, &Mlcp::d);
    // identities between eq. 3-16 written out and its sparse form, to rounding (1e-12 relative)
    CHECK((dense.eta - eta).norm() <= 1e-12 * eta.norm());
    CHECK((dense.JB.diagonal() - d).norm() <= 1e-12 * d.norm());
    CHECK((dense_b_transpose(mlcp) - dense.J * dense.inverse_mass).norm() <= 1e-12 * dense.J.norm());
    const Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(mlcp.row_count(), -5.0, 7.0);
    // eq. 3-23: W = J B λ − η
    const Eigen::VectorXd W = dense.JB * lambda - dense.eta;
    CHECK((mlcp.slack(lambda.data()) - W).norm() <= 1e-12 * W.norm());
    // eq. 3-11: F_c = Jᵀ λ
    std::vector<RigidBody> pushed = bodies;
    for (RigidBody& b : pushed) b.clear_forces();
    mlcp.add_constraint_forces(pushed, lambda.data());
    const Eigen::VectorXd F_c = dense.J.transpose() * lambda;
    CHECK((stacked_external_force(pushed) - F_c).norm() <= 1e-12 * F_c.norm());
  }

  TEST_CASE("the MLCP's text-form views equal the independent dense reference") {
    // Random systems of 2 to 4 bodies and 1 to 6 rows, in both layouts (block_layout.h).
    std::mt19937 rng(31);
    for (const Layout layout : {Layout::general, Layout::planar}) {
      for (int trial = 0; trial < 12; ++trial) {
        CAPTURE(trial);
        const RandomSystem sys = random_system(rng, 2 + trial % 3, 1 + trial % 6, false, layout);
        const DenseSystem& dense = sys.dense;
        REQUIRE(block_size(sys.mlcp) == (layout == Layout::planar ? 3 : 6));
        const Eigen::MatrixXd J = dense_jacobian(sys.mlcp);
        const Eigen::MatrixXd B = dense_b_transpose(sys.mlcp).transpose();
        // eq. 3-8, exact: both place the written Jsp in the same columns (the planar layout
        // cuts and widens it, dropping only exact zeros)
        CHECK(J == dense.J);
        // The rest agrees to rounding: the dense products sum the same few nonzero products
        // (≤ 3 per entry of B, ≤ 12 per entry of J B and of J M⁻¹ F_ext) in another order,
        // with exact zeros in between. 1e-14 relative to the norm (measured ≤ 3e-16) is
        // rounding; a wrong term would be of the size of the entries.
        // eq. 3-12, 3-16: B = M⁻¹ Jᵀ (the text's Convert)
        CHECK((B - dense.inverse_mass * dense.J.transpose()).norm() <= 1e-14 * B.norm());
        // eq. 3-16: J B = J M⁻¹ Jᵀ, and its diagonal d
        CHECK((J * B - dense.JB).norm() <= 1e-14 * dense.JB.norm());
        CHECK((per_row(sys.mlcp, &Mlcp::d) - dense.JB.diagonal()).norm() <= 1e-14 * dense.JB.norm());
        // eq. 3-16: η = ζ/Δt − J (V/Δt + M⁻¹ F_ext)
        CHECK((per_row(sys.mlcp, &Mlcp::eta) - dense.eta).norm() <= 1e-14 * dense.eta.norm());
        // eq. 3-23: W = J B λ − η, for λ in [−60, 60] N
        const Eigen::VectorXd lambda = random_matrix(rng, sys.mlcp.row_count(), 1, 60.0);
        const Eigen::VectorXd W = dense.JB * lambda - dense.eta;
        const double scale = dense.JB.norm() * lambda.norm() + dense.eta.norm();
        CHECK((sys.mlcp.slack(lambda.data()) - W).norm() <= 1e-14 * scale);
      }
    }
  }
}
