// The chapter-3 constraints in motion: the incline of Fig 3-1, pendulums, a joint-angle limit,
// and the facts of eq. 3-11 (equal and opposite forces, no work), on planar scenes (x–y, y up).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/LU>

#include "constraints/angle_limit.h"
#include "constraints/constrained_step.h"
#include "constraints/dense_system.h"
#include "constraints/distance_constraint.h"
#include "constraints/incline_constraint.h"
#include "constraints/jacobian_rows.h"
#include "constraints/revolute_joint.h"
#include "kinematics/momentum.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, in m/s²

double relative_error(double value, double expected) {
  return std::abs(value - expected) / std::abs(expected);
}

// The largest |component| that a planar scene must keep at exactly zero: z of x and v, x and y
// of ω, and x and y of q (a rotation about z only).
double out_of_plane(const RigidBody& body) {
  return std::max({std::abs(body.x.z()), std::abs(body.v.z()), std::abs(body.angular_velocity.x()),
                   std::abs(body.angular_velocity.y()), std::abs(body.q.x()), std::abs(body.q.y())});
}

// What a run of steps recorded for body 0.
struct Trace {
  std::vector<double> x;      // body 0's x after each step, in m
  std::vector<double> C;      // constraint error |x − pivot| − L after each step, in m
  double max_speed = 0.0;     // largest |v| of body 0, in m/s
  double out_of_plane = 0.0;  // largest out_of_plane(body 0) seen
};

// Steps the scene and records body 0, taking C as its distance from the origin minus length.
Trace run(std::vector<RigidBody>& bodies, const ConstraintList& constraints,
          const ConstrainedStepSettings& settings, int steps, double length) {
  Trace trace;
  WarmStart warm_start;
  for (int k = 0; k < steps; ++k) {
    constrained_step(bodies, constraints, settings, warm_start);
    trace.x.push_back(bodies[0].x.x());
    trace.C.push_back(bodies[0].x.norm() - length);
    trace.max_speed = std::max(trace.max_speed, bodies[0].v.norm());
    trace.out_of_plane = std::max(trace.out_of_plane, out_of_plane(bodies[0]));
  }
  return trace;
}

// The mean time between upward zero crossings of x, each crossing time interpolated linearly.
double measured_period(const std::vector<double>& x, double dt) {
  std::vector<double> crossings;
  for (size_t k = 1; k < x.size(); ++k) {
    if (x[k - 1] < 0.0 && x[k] >= 0.0) crossings.push_back(dt * (k - x[k] / (x[k] - x[k - 1])));
  }
  REQUIRE(crossings.size() >= 3);
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

// A disc of radius 5 cm (a near point mass) at angle θ0 from hanging straight down, L from the
// origin, held there by a distance constraint from the world origin to its centre.
ConstraintList simple_pendulum(std::vector<RigidBody>& bodies, double length, double theta0) {
  bodies.push_back(disc_body(100.0, 0.05, length * Vec3(std::sin(theta0), -std::cos(theta0), 0.0)));
  ConstraintList constraints;
  constraints.push_back(std::make_unique<DistanceConstraint>(Anchor{world, Vec3::Zero()},
                                                             Anchor{0, Vec3::Zero()}, length));
  return constraints;
}

// A rod 1 m × 5 cm pinned at one end to the world origin, its centre at angle from +x.
ConstraintList pinned_rod(std::vector<RigidBody>& bodies, double angle) {
  bodies.push_back(box_body(10.0, 0.5, 0.025, 0.5 * Vec3(std::cos(angle), std::sin(angle), 0.0), angle));
  ConstraintList constraints;
  constraints.push_back(std::make_unique<RevoluteJoint>(anchor_at(bodies, world, Vec3::Zero()),
                                                        anchor_at(bodies, 0, Vec3::Zero())));
  return constraints;
}

// The constraint forces F_c = Jᵀ λ alone (eq. 3-11), per body, for one solve of the rows at the
// bodies' current state under gravity and the forces already on them.
std::vector<RigidBody> constraint_forces(std::vector<RigidBody> bodies,
                                         const ConstraintList& constraints, double dt,
                                         Eigen::VectorXd& lambda) {
  apply_gravity(bodies, Vec3(0.0, -g, 0.0));
  const Mlcp mlcp = assemble_mlcp(bodies, write_all_rows(bodies, constraints, dt, 0.2), dt);
  lambda = solve_pgs(mlcp, Eigen::VectorXd::Zero(mlcp.eta.size()), {50, 0.0, false}).lambda;
  for (RigidBody& body : bodies) body.clear_forces();
  apply_constraint_forces(bodies, mlcp.rows, lambda);
  return bodies;
}

// Three boxes in a chain pinned to the world, a rope from the last one to the world, a limit on
// the first joint's angle, a box on an incline, and a static body pinned to a fifth box.
ConstraintList mixed_scene(std::vector<RigidBody>& bodies) {
  for (int k = 0; k < 3; ++k) bodies.push_back(box_body(5.0, 0.3, 0.1, Vec3(0.6 * k + 0.3, 0.0, 0.0), 0.1 * k));
  bodies.push_back(box_body(2.0, 0.2, 0.2, Vec3(3.0, 1.0, 0.0), 0.4));
  bodies.push_back(RigidBody::static_body(Vec3(5.0, 0.0, 0.0), planar_orientation(0.3)));
  bodies.push_back(box_body(2.0, 0.4, 0.1, Vec3(5.5, -0.2, 0.0), -0.2));
  ConstraintList c;
  for (int k = 0; k < 3; ++k) {
    const Vec3 pivot(0.6 * k, 0.0, 0.0);
    c.push_back(std::make_unique<RevoluteJoint>(anchor_at(bodies, k == 0 ? world : k - 1, pivot),
                                                anchor_at(bodies, k, pivot)));
  }
  c.push_back(std::make_unique<DistanceConstraint>(Anchor{world, Vec3(2.0, 1.0, 0.0)},
                                                   Anchor{2, Vec3(0.3, 0.1, 0.0)}, 1.2));
  c.push_back(std::make_unique<AngleLimit>(0, 1, -0.05, LimitSide::lower));
  c.push_back(std::make_unique<InclineConstraint>(3, Vec3(3.0, 0.9, 0.0), Vec3(0.6, 0.8, 0.0)));
  c.push_back(std::make_unique<RevoluteJoint>(anchor_at(bodies, 4, Vec3(5.2, -0.1, 0.0)),
                                              anchor_at(bodies, 5, Vec3(5.2, -0.1, 0.0))));
  return c;
}

// mixed_scene with random velocities and forces on every dynamic body, from a seed.
ConstraintList shaken_mixed_scene(std::vector<RigidBody>& bodies, unsigned seed) {
  ConstraintList constraints = mixed_scene(bodies);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (RigidBody& b : bodies) {
    if (b.is_static()) continue;
    b.v = Vec3(u(rng), u(rng), u(rng));
    b.angular_velocity = Vec3(u(rng), u(rng), u(rng));
    b.force = 10.0 * Vec3(u(rng), u(rng), u(rng));
    b.torque = Vec3(u(rng), u(rng), u(rng));
  }
  return constraints;
}

void set_velocities(std::vector<RigidBody>& bodies, const Eigen::VectorXd& V) {
  for (size_t b = 0; b < bodies.size(); ++b) {
    bodies[b].v = V.segment<3>(6 * b);
    bodies[b].angular_velocity = V.segment<3>(6 * b + 3);
  }
}

}  // namespace

TEST_SUITE("Constraints") {
  TEST_CASE("Fig 3-1: a body on an incline slides with g sin θ, held by m g cos θ") {
    for (double degrees : {10.0, 30.0, 45.0, 60.0}) {
      const double theta = degrees * M_PI / 180.0;
      const Vec3 N(std::sin(theta), std::cos(theta), 0.0);          // the incline's normal
      const Vec3 downhill(std::cos(theta), -std::sin(theta), 0.0);  // along the slope, down
      const Vec3 p(0.0, 1.0, 0.0);
      std::vector<RigidBody> bodies{box_body(4.0, 0.5, 0.25, p)};  // m = 2 kg
      ConstraintList constraints;
      constraints.push_back(std::make_unique<InclineConstraint>(0, p, N));
      const ConstrainedStepSettings settings;
      WarmStart warm_start;
      for (int k = 0; k < 30; ++k) {
        const double before = bodies[0].v.dot(downhill);
        StepReport report;
        constrained_step(bodies, constraints, settings, warm_start, &report);
        // analytic: a = g sin θ along the slope (g·downhill), and λ = m g cos θ (−m g·N);
        // one row is solved exactly by the first sweep, so 1e-9 relative is rounding only
        CHECK(relative_error((bodies[0].v.dot(downhill) - before) / settings.dt, g * std::sin(theta)) <= 1e-9);
        CHECK(relative_error(report.solution.lambda[0], 2.0 * g * std::cos(theta)) <= 1e-9);
        // eq. 3-1: the body stays on the line (C stays at rounding level, 1e-12 m)
        CHECK(std::abs((bodies[0].x - p).dot(N)) <= 1e-12);
      }
    }
  }

  TEST_CASE("Fig 3-1 as the solver sees it: J, ζ, η, bounds, λ, W for a 30° incline") {
    // m = 2 kg at rest, ε = 1 cm off the incline's line, β = 0.2, Δt = 1/60 s, g = (0, −9.8, 0)
    const double theta = M_PI / 6.0;
    const Vec3 N(std::sin(theta), std::cos(theta), 0.0);
    const Vec3 p(0.0, 1.0, 0.0);
    const double epsilon = 0.01;
    std::vector<RigidBody> bodies{box_body(4.0, 0.5, 0.25, p + epsilon * N)};
    ConstraintList constraints;
    constraints.push_back(std::make_unique<InclineConstraint>(0, p, N));
    const ConstrainedStepSettings settings;  // Δt = 1/60 s, β = 0.2
    WarmStart warm_start;
    StepReport report;
    constrained_step(bodies, constraints, settings, warm_start, &report);
    MESSAGE("Fig 3-1, θ = 30°, m = 2 kg, ε = 0.01 m, β = 0.2, Δt = 1/60 s:\n" << format_step_report(report));
    const ConstraintRow& row = report.mlcp.rows[0];
    // J = [Nᵀ 0ᵀ] (text, Fig 3-1 applied); one-body row against the world
    CHECK((row.Jsp[0].head<3>() - N).norm() == 0.0);
    CHECK(row.Jsp[0].tail<3>().norm() == 0.0);
    CHECK(row.Jmap[1] == world);
    // eq. 3-14: ζ = −β ε / Δt = −0.12 m/s
    CHECK(row.zeta == doctest::Approx(-0.2 * epsilon * 60.0).epsilon(1e-12));
    // eq. 3-16 with V = 0: η = ζ/Δt − N·g = −7.2 + 9.8 cos 30° m/s²
    const double eta = -7.2 + g * std::cos(theta);
    CHECK(report.mlcp.eta[0] == doctest::Approx(eta).epsilon(1e-12));
    // d = J M⁻¹ Jᵀ = 1/m; λ = η / d = m η
    CHECK(report.mlcp.d[0] == doctest::Approx(0.5).epsilon(1e-12));
    CHECK(report.solution.lambda[0] == doctest::Approx(2.0 * eta).epsilon(1e-12));
    CHECK(std::abs(report.W[0]) <= 1e-12);
    // after the step ε is (1 − β) ε (eq. 3-14 with Δt written out, constraint.h)
    CHECK((bodies[0].x - p).dot(N) == doctest::Approx(0.8 * epsilon).epsilon(1e-9));
  }

  TEST_CASE("a simple pendulum swings with period 2π√(L/g) and stays in the plane") {
    // L = 1 m, θ0 = 0.05 rad (the amplitude adds θ0²/16 = 0.016 % to the period), Δt = 1/240 s
    std::vector<RigidBody> bodies;
    const ConstraintList rod = simple_pendulum(bodies, 1.0, 0.05);
    ConstrainedStepSettings settings;
    settings.dt = 1.0 / 240.0;
    const Trace trace = run(bodies, rod, settings, 2400, 1.0);
    const double period = measured_period(trace.x, settings.dt);
    MESSAGE("simple pendulum: period " << period << " s, 2π√(L/g) = " << 2.0 * M_PI * std::sqrt(1.0 / g) << " s");
    // analytic small-angle period, within 1 %
    CHECK(relative_error(period, 2.0 * M_PI * std::sqrt(1.0 / g)) <= 0.01);
    // planar scene: every out-of-plane component stays exactly zero
    CHECK(trace.out_of_plane == 0.0);
  }

  TEST_CASE("a rod on a revolute joint swings with period 2π√(I_pivot / (m g d))") {
    // rod 1 m long pinned at its end, d = 0.5 m from pivot to centre, θ0 = 0.05 rad, Δt = 1/240 s
    std::vector<RigidBody> bodies;
    const ConstraintList pin = pinned_rod(bodies, -M_PI / 2.0 + 0.05);
    ConstrainedStepSettings settings;
    settings.dt = 1.0 / 240.0;
    const RigidBody& rod = bodies[0];
    const double I_pivot = rod.inertia_body(2, 2) + rod.mass * 0.25;  // parallel axes
    const double expected = 2.0 * M_PI * std::sqrt(I_pivot / (rod.mass * g * 0.5));
    const Trace trace = run(bodies, pin, settings, 2400, 0.5);
    const double period = measured_period(trace.x, settings.dt);
    MESSAGE("pinned rod: period " << period << " s, 2π√(I_pivot/(m g d)) = " << expected << " s");
    // analytic physical-pendulum period (about 2π√(2L/3g) for a thin rod), within 1 %
    CHECK(relative_error(period, expected) <= 0.01);
    CHECK(trace.out_of_plane == 0.0);
  }

  TEST_CASE("pendulum drift: grows without bias, bounded by Δt² v² / (2 L β) with it") {
    // L = 1 m, θ0 = 1 rad, Δt = 1/60 s, 10 s. With the row solved exactly, one step moves the
    // bob from distance L + C to √((L + (1 − β) C)² + Δt² v_t²) (v_t ⟂ the rod), so
    //   β = 0:  C never decreases, and grows by ~Δt² v_t² / (2L) every step;
    //   β > 0:  C_{k+1} ≤ (1 − β) C_k + Δt² v²/(2L), hence 0 ≤ C ≤ Δt² v_max² / (2 L β).
    ConstrainedStepSettings settings;
    std::vector<RigidBody> loose;
    settings.beta = 0.0;
    const Trace drift = run(loose, simple_pendulum(loose, 1.0, 1.0), settings, 600, 1.0);
    for (size_t k = 1; k < drift.C.size(); ++k) CHECK(drift.C[k] >= drift.C[k - 1] - 1e-12);
    // it keeps growing: after 10 s more than three times its value after 2.5 s
    CHECK(drift.C.back() > 3.0 * drift.C[149]);
    std::vector<RigidBody> held;
    settings.beta = 0.2;
    const Trace bias = run(held, simple_pendulum(held, 1.0, 1.0), settings, 600, 1.0);
    const double bound = settings.dt * settings.dt * bias.max_speed * bias.max_speed / (2.0 * settings.beta);
    const auto [low, high] = std::minmax_element(bias.C.begin(), bias.C.end());
    CHECK(*low >= -1e-12);
    CHECK(*high <= bound);
    MESSAGE("drift after 10 s: β = 0: " << drift.C.back() << " m; β = 0.2: max " << *high
                                       << " m, bound " << bound << " m");
    CHECK(drift.C.back() > *high);
  }

  TEST_CASE("a joint-angle limit stops a falling rod and then holds it with m g (L/2) cos θ_L") {
    // rod 1 m pinned at its end, released horizontal; it may not turn past θ_L = ∓45°. Mirrored
    // for the upper side: gravity up, the rod swings up to +45°.
    for (const LimitSide side : {LimitSide::lower, LimitSide::upper}) {
      const double s = side == LimitSide::lower ? 1.0 : -1.0;
      std::vector<RigidBody> bodies;
      ConstraintList constraints = pinned_rod(bodies, 0.0);
      constraints.push_back(std::make_unique<AngleLimit>(world, 0, -s * M_PI / 4.0, side));
      ConstrainedStepSettings settings;
      settings.gravity = Vec3(0.0, -s * g, 0.0);
      settings.pgs.iterations = 30;
      WarmStart warm_start;
      StepReport report;
      const auto C = [&] { return s * (planar_angle(bodies[0].q) + s * M_PI / 4.0); };
      for (int k = 0; k < 180; ++k) {
        const bool far = C() > 0.1;
        constrained_step(bodies, constraints, settings, warm_start, &report);
        // eq. 3-24 at λ⁻ = 0: a step that starts far from the limit gets no push from it
        if (far) CHECK(report.solution.lambda[2] == 0.0);
        // eq. 3-17: the limit holds to 1e-3 rad (PGS is stopped at 30 sweeps)
        CHECK(C() >= -1e-3);
      }
      // at rest on the limit: the limit's torque balances gravity's about the pin (statics)
      CHECK(std::abs(bodies[0].angular_velocity.z()) <= 1e-3);
      CHECK(relative_error(report.solution.lambda[2], bodies[0].mass * g * 0.5 * std::cos(M_PI / 4.0)) <= 1e-3);
      CHECK(std::abs(report.W[2]) <= 1e-3);
    }
  }

  TEST_CASE("eq. 3-11: a row against a static body and against the world push equal and opposite") {
    std::vector<RigidBody> bodies{box_body(3.0, 0.4, 0.2, Vec3(1.0, 0.2, 0.0), 0.3),
                                  RigidBody::static_body(Vec3(0.0, 0.5, 0.0), planar_orientation(0.7))};
    bodies[0].v = Vec3(0.5, -1.0, 0.0);
    bodies[0].angular_velocity = Vec3(0.0, 0.0, 2.0);
    const Vec3 p_static(0.1, 0.6, 0.0);
    const Anchor on_box = anchor_at(bodies, 0, Vec3(1.3, 0.3, 0.0));
    ConstraintList two_body, one_body;
    two_body.push_back(std::make_unique<DistanceConstraint>(anchor_at(bodies, 1, p_static), on_box, 1.3));
    one_body.push_back(std::make_unique<DistanceConstraint>(Anchor{world, p_static}, on_box, 1.3));
    Eigen::VectorXd lambda_two, lambda_one;
    const std::vector<RigidBody> two = constraint_forces(bodies, two_body, 1.0 / 60.0, lambda_two);
    const std::vector<RigidBody> one = constraint_forces(bodies, one_body, 1.0 / 60.0, lambda_one);
    // identity: a static body adds nothing to J M⁻¹ Jᵀ or η, so λ and the box's force agree
    CHECK(lambda_two[0] == doctest::Approx(lambda_one[0]).epsilon(1e-12));
    CHECK((two[0].force - one[0].force).norm() <= 1e-12 * one[0].force.norm());
    CHECK((two[0].torque - one[0].torque).norm() <= 1e-12 * one[0].torque.norm());
    // eq. 3-11: on the static body the force is opposite, and the torques about its centre cancel
    CHECK((two[1].force + two[0].force).norm() <= 1e-12 * two[0].force.norm());
    const Vec3 moment = two[1].torque + two[0].torque + (two[0].x - two[1].x).cross(two[0].force);
    CHECK(moment.norm() <= 1e-12 * two[0].force.norm());
  }

  TEST_CASE("eq. 3-11: constraint forces do no work on velocities with J V = 0") {
    std::vector<RigidBody> bodies;
    const ConstraintList constraints = shaken_mixed_scene(bodies, 23);
    // V projected onto J V = 0: V − Jᵀ (J Jᵀ)⁻¹ J V
    const Eigen::MatrixXd J = dense_jacobian(write_all_rows(bodies, constraints, 1.0 / 60.0, 0.2),
                                             static_cast<int>(bodies.size()));
    Eigen::VectorXd V = stacked_velocity(bodies);
    V -= J.transpose() * (J * J.transpose()).partialPivLu().solve(J * V);
    set_velocities(bodies, V);
    REQUIRE((J * V).norm() <= 1e-12 * V.norm());
    Eigen::VectorXd lambda;
    const std::vector<RigidBody> forces = constraint_forces(bodies, constraints, 1.0 / 60.0, lambda);
    double work = 0.0, scale = 0.0;
    for (const RigidBody& b : forces) {
      // eq. 1-48: the power F·v + τ·ω of the constraint force on each body
      work += power(b.force, b.v, b.torque, b.angular_velocity);
      scale += b.force.norm() * b.v.norm() + b.torque.norm() * b.angular_velocity.norm();
    }
    // eq. 3-11: F_c·V = λᵀ J V = 0, to rounding (1e-12 of the terms' size)
    CHECK(std::abs(work) <= 1e-12 * scale);
    CHECK(scale > 1.0);
  }

  TEST_CASE("the dense path agrees with the sparse one: η, diagonal d, Bᵀ, W and Jᵀ λ") {
    std::vector<RigidBody> bodies;
    const ConstraintList constraints = shaken_mixed_scene(bodies, 29);
    const double dt = 1.0 / 60.0;
    const std::vector<ConstraintRow> rows = write_all_rows(bodies, constraints, dt, 0.2);
    const Mlcp mlcp = assemble_mlcp(bodies, rows, dt);
    const DenseSystem dense = build_dense_system(bodies, rows, dt);
    // identities between eq. 3-16 written out and its sparse form, to rounding (1e-12 relative)
    CHECK((dense.eta - mlcp.eta).norm() <= 1e-12 * mlcp.eta.norm());
    CHECK((dense.JB.diagonal() - mlcp.d).norm() <= 1e-12 * mlcp.d.norm());
    CHECK((dense_b_transpose(mlcp) - dense.J * dense.inverse_mass).norm() <= 1e-12 * dense.J.norm());
    const Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(mlcp.eta.size(), -5.0, 7.0);
    // eq. 3-23: W = J B λ − η
    const Eigen::VectorXd W = dense.JB * lambda - dense.eta;
    CHECK((complementarity_slack(mlcp, lambda) - W).norm() <= 1e-12 * W.norm());
    // eq. 3-11: F_c = Jᵀ λ
    std::vector<RigidBody> pushed = bodies;
    for (RigidBody& b : pushed) b.clear_forces();
    apply_constraint_forces(pushed, rows, lambda);
    const Eigen::VectorXd F_c = dense.J.transpose() * lambda;
    CHECK((stacked_external_force(pushed) - F_c).norm() <= 1e-12 * F_c.norm());
  }

  TEST_CASE("a step that fills a report moves the bodies bit for bit as one that does not") {
    std::vector<RigidBody> plain, reported;
    const ConstraintList constraints = mixed_scene(plain);
    mixed_scene(reported);
    const ConstrainedStepSettings settings;
    WarmStart plain_start, reported_start;
    for (int k = 0; k < 30; ++k) {
      StepReport report;
      constrained_step(plain, constraints, settings, plain_start);
      constrained_step(reported, constraints, settings, reported_start, &report);
    }
    // determinism: the report only observes (exact equality)
    for (size_t b = 0; b < plain.size(); ++b) {
      CHECK(plain[b].x == reported[b].x);
      CHECK(plain[b].q.coeffs() == reported[b].q.coeffs());
      CHECK(plain[b].v == reported[b].v);
      CHECK(plain[b].angular_velocity == reported[b].angular_velocity);
    }
  }

  TEST_CASE("warm start reuses last step's λ only for rows on the same bodies") {
    std::vector<ConstraintRow> rows(2);
    rows[0].Jmap = {0, world};
    rows[1].Jmap = {0, 1};
    WarmStart warm_start;
    warm_start.remember(rows, Eigen::Vector2d(3.0, 4.0));
    CHECK(warm_start.guess(rows) == Eigen::Vector2d(3.0, 4.0));
    rows[1].Jmap = {1, 0};
    CHECK(warm_start.guess(rows) == Eigen::Vector2d::Zero());
    rows.pop_back();
    CHECK(warm_start.guess(rows) == Eigen::VectorXd::Zero(1));
  }

  TEST_CASE("constraints reject bad input with std::invalid_argument") {
    CHECK_THROWS_AS(InclineConstraint(0, Vec3::Zero(), Vec3(0.0, 2.0, 0.0)), std::invalid_argument);
    CHECK_THROWS_AS(InclineConstraint(-1, Vec3::Zero(), Vec3::UnitY()), std::invalid_argument);
    CHECK_THROWS_AS(DistanceConstraint(Anchor{0, Vec3::Zero()}, Anchor{0, Vec3::UnitX()}, 1.0),
                    std::invalid_argument);
    CHECK_THROWS_AS(DistanceConstraint(Anchor{world, Vec3::Zero()}, Anchor{0, Vec3::Zero()}, 0.0),
                    std::invalid_argument);
    CHECK_THROWS_AS(RevoluteJoint(Anchor{world, Vec3::Zero()}, Anchor{world, Vec3::UnitX()}),
                    std::invalid_argument);
    CHECK_THROWS_AS(AngleLimit(0, 1, 4.0, LimitSide::lower), std::invalid_argument);
    CHECK_THROWS_AS(AngleLimit(-2, 1, 0.0, LimitSide::upper), std::invalid_argument);
  }
}
