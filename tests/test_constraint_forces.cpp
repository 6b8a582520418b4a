// The facts of eq. 3-11, F_c = Jᵀ λ: a row pushes its two bodies equal and opposite, a static
// body the same as the world, and constraint forces do no work on velocities the constraints
// allow. Planar scenes (x–y, y up).
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/LU>

#include "constraints/dense_system.h"
#include "constraints/distance_constraint.h"
#include "constraints/jacobian_rows.h"
#include "constraints/pgs_solver.h"
#include "kinematics/momentum.h"
#include "motion/integrator.h"
#include "support/constraint_scenes.h"

using namespace lamina;

namespace {

constexpr double g = 9.8;  // |gravity|, in m/s²

// The constraint forces F_c = Jᵀ λ alone (eq. 3-11), per body, for one solve of the rows at the
// bodies' current state under gravity and the forces already on them.
std::vector<RigidBody> constraint_forces(std::vector<RigidBody> bodies,
                                         const ConstraintList& constraints, double dt,
                                         Eigen::VectorXd& lambda) {
  apply_gravity(bodies, Vec3(0.0, -g, 0.0));
  const Mlcp mlcp = assemble_mlcp(bodies, write_all_rows(bodies, constraints, dt, 0.2), dt);
  lambda = solve_pgs(mlcp, Eigen::VectorXd::Zero(mlcp.row_count()), {50, 0.0, false}).lambda;
  for (RigidBody& body : bodies) body.clear_forces();
  mlcp.add_constraint_forces(bodies, lambda.data());
  return bodies;
}

void set_velocities(std::vector<RigidBody>& bodies, const Eigen::VectorXd& V) {
  for (size_t b = 0; b < bodies.size(); ++b) {
    bodies[b].v = V.segment<3>(6 * b);
    bodies[b].angular_velocity = V.segment<3>(6 * b + 3);
  }
}

}  // namespace

TEST_SUITE("ConstraintForces") {
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
    // eq. 5-8: a static body, like the world, holds no block of J, so F_c = Jᵀ λ gives it nothing
    CHECK(two[1].force == Vec3::Zero());
    CHECK(two[1].torque == Vec3::Zero());
    // eq. 3-11: the same rod to a moving body in the static body's place pushes it opposite,
    // and the torques about its centre cancel
    std::vector<RigidBody> moving = bodies;
    moving[1] = box_body(3.0, 0.4, 0.2, bodies[1].x, 0.7);
    ConstraintList between;
    between.push_back(std::make_unique<DistanceConstraint>(anchor_at(moving, 1, p_static), on_box, 1.3));
    Eigen::VectorXd lambda_between;
    const std::vector<RigidBody> pair = constraint_forces(moving, between, 1.0 / 60.0, lambda_between);
    CHECK((pair[1].force + pair[0].force).norm() <= 1e-12 * pair[0].force.norm());
    const Vec3 moment = pair[1].torque + pair[0].torque + (pair[0].x - pair[1].x).cross(pair[0].force);
    CHECK(moment.norm() <= 1e-12 * pair[0].force.norm());
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
}
