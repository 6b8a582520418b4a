// Random small constraint systems for the solver and assembly tests: random bodies, random
// rows on them, and the MLCP of eq. 3-16 both as Lamina assembles it and written out dense.
// Every draw comes from the caller's seeded std::mt19937 (STYLE 9), so a test sees the same
// system on every run.
#pragma once

#include <random>
#include <vector>

#include <Eigen/Core>

#include "constraints/dense_system.h"
#include "constraints/mlcp.h"

namespace lamina {

inline constexpr double random_system_dt = 1.0 / 60.0;  // Δt of every random system, in s

// A matrix with entries uniform in [−scale, scale] (seeded; Eigen's Random would use rand()).
Eigen::MatrixXd random_matrix(std::mt19937& rng, Eigen::Index rows, Eigen::Index cols, double scale);

Vec6 random_vec6(std::mt19937& rng);  // entries uniform in [−1, 1]

// Which way a random system's rows and inertias point (block_layout.h):
//   general  every way, so that its MLCP is assembled in the general layout [v ω];
//   planar   rows with v_z = ω_x = ω_y = 0 on bodies turned about z only, so that it is
//            assembled in the planar layout [v_x v_y ω_z].
// Both take the same draws from the generator; planar drops what leaves the plane.
enum class Layout { general, planar };

// A dynamic body: mass in [1, 5] kg, principal inertias in [0.5, 2] kg·m² on randomly turned
// axes, and random velocity and accumulated force (they make η).
RigidBody random_body(std::mt19937& rng, Layout layout = Layout::general);

struct RandomSystem {
  std::vector<RigidBody> bodies;    // the bodies the rows act on
  std::vector<ConstraintRow> rows;  // the rows as written
  Mlcp mlcp;                        // the sparse MLCP the solver sees
  DenseSystem dense;                // the same system written out (the independent reference)
};

// `row_count` rows on `body_count` random bodies, each on a random body pair (one in three
// against the world), Jsp entries in [−1, 1], ζ in [−1, 1] m/s. `bounded` gives each row bounds
// of one of eq. 3-26's three kinds at random: equality, contact [0, ∞), or a box [λ⁻, λ⁺] with
// λ⁻ in [−60, 30] N and a width in [1, 60] N (λ of these systems is ~ ±60 N); otherwise none.
RandomSystem random_system(std::mt19937& rng, int body_count, int row_count, bool bounded,
                           Layout layout = Layout::general);

// A random MLCP with all three kinds of row of eq. 3-26: equality (−∞, ∞), contact [0, ∞), and
// friction ±μ λc (μ in [0.2, 1]) bounded by an earlier contact row (chapter 4 puts friction
// rows after their contact row). Rows and bodies as random_system draws them.
RandomSystem random_mlcp_with_friction(std::mt19937& rng, int body_count, int row_count,
                                       Layout layout = Layout::general);

}  // namespace lamina
