// PGS's sweeps on threads (issue 19, pgs_solver.h): λ of an MLCP swept on 2 and 3 threads must
// be one thread's λ bit for bit — from a warm start and from λ = 0, with rows in no order of
// place (then the sweeps stay on one thread) and with rows whose lanes both wait on other
// threads; F_c = Jᵀ λ added in the last sweep must be Mlcp::add_constraint_forces's; and two
// MLCPs swept side by side, each to the λ it has when solved alone. The lanes of one thread:
// test_pgs_lanes.cpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#include "constraints/pgs_solver.h"
#include "parallel/workers.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"
#include "support/pgs_support.h"

using namespace lamina;

namespace {

// λ after `sweeps` sweeps by a solver given a team of `threads`, and whether it swept on them.
struct OnThreads {
  std::vector<unsigned char> lambda;
  bool swept_on_threads = false;
};
OnThreads solved_on_threads(int threads, const StepReport& step, int sweeps,
                            Pitfalls pitfalls = {}) {
  Workers workers(threads);
  PgsSolver solver;
  solver.use_workers(&workers);
  OnThreads out;
  out.lambda = solved(solver, step, sweeps, pitfalls);
  out.swept_on_threads = solver.swept_on_threads();
  return out;
}

// A velocity MLCP and a position MLCP solved side by side (PgsSolver::solve_both) by a solver
// given a team of `threads` (none for 0): both λ, and the position solve's B λ per body.
struct SideBySide {
  std::vector<unsigned char> velocity;
  std::vector<unsigned char> position;
  std::vector<Vec6> velocity_change;
  bool side_by_side = false;
};
SideBySide solved_side_by_side(int threads, const StepReport& velocity,
                               const StepReport& position, int position_sweeps,
                               Pitfalls pitfalls = {}) {
  std::unique_ptr<Workers> workers(threads > 0 ? new Workers(threads) : nullptr);
  PgsSolver solver;
  solver.use_workers(workers.get());
  std::vector<double> v(velocity.lambda_exp.data(),
                        velocity.lambda_exp.data() + velocity.lambda_exp.size());
  std::vector<double> p(position.lambda_exp.data(),
                        position.lambda_exp.data() + position.lambda_exp.size());
  SweepResult v_result;
  SweepResult p_result;
  const bool record = position_sweeps < 0;  // a recorded second solve: one after the other
  solver.solve_both(velocity.mlcp, v.data(), {8, 0.0, false}, v_result, position.mlcp, p.data(),
                    {record ? 3 : position_sweeps, 0.0, record}, p_result, pitfalls);
  SideBySide out;
  out.velocity = bytes_of(v.data(), v.size());
  out.position = bytes_of(p.data(), p.size());
  for (int b = 0; b < position.mlcp.body_count(); ++b) {
    out.velocity_change.push_back(solver.velocity_change(b));
  }
  out.side_by_side = solver.swept_side_by_side();
  return out;
}

// Every body's force and torque, all six components each, as bytes.
std::vector<unsigned char> wrenches_of(const std::vector<RigidBody>& bodies) {
  std::vector<double> values;
  for (const RigidBody& body : bodies) {
    values.insert(values.end(), body.force.data(), body.force.data() + 3);
    values.insert(values.end(), body.torque.data(), body.torque.data() + 3);
  }
  return bytes_of(values.data(), values.size());
}

}  // namespace

TEST_SUITE("PGS on threads") {
  TEST_CASE("F_c = Jᵀ λ added in PGS's last sweep is Mlcp::add_constraint_forces's, bit for bit") {
    // With `forces_to`, sweeps in parts add each group's terms of F_c once its λ are final
    // (pgs_solver.h). Every body's force and torque must be what solving first and then adding
    // F_c row by row gives — the same additions in the same order, so the same bits, not close
    // ones — in two lanes, on 2 and 3 threads, side by side with the position MLCP (the first
    // MLCP's F_c alone), and where the sweeps do not run in parts (recorded: added after them).
    // The forces start from values with bits below gravity's, so that a sum taken in another
    // order, a term added twice or one left out shows; the out-of-plane components stay 0.
    const WorldReport report = report_after(60);
    const StepReport& velocity = report.velocity;
    REQUIRE(velocity.mlcp.row_count() >= 1000);
    std::vector<RigidBody> start = report.bodies;
    for (std::size_t b = 0; b < start.size(); ++b) {
      start[b].force = Vec3(0.013 * static_cast<double>(b), -9.8 * start[b].mass + 1e-3, 0.0);
      start[b].torque = Vec3(0.0, 0.0, 0.007 * static_cast<double>(b) - 0.5);
    }
    for (const int sweeps : {1, 8}) {
      CAPTURE(sweeps);
      std::vector<double> lambda(velocity.lambda_exp.data(),
                                 velocity.lambda_exp.data() + velocity.lambda_exp.size());
      SweepResult recorded;
      PgsSolver row_by_row;
      row_by_row.solve(velocity.mlcp, lambda.data(), {sweeps, 0.0, true}, recorded);
      std::vector<RigidBody> expected = start;
      velocity.mlcp.add_constraint_forces(expected, lambda.data());
      const std::vector<unsigned char> expected_lambda = bytes_of(lambda.data(), lambda.size());
      const std::vector<unsigned char> expected_wrenches = wrenches_of(expected);
      REQUIRE(expected_wrenches != wrenches_of(start));
      for (const int threads : {0, 2, 3}) {
        for (const bool both : {false, true}) {
          for (const bool record : {false, true}) {
            CAPTURE(threads);
            CAPTURE(both);
            CAPTURE(record);
            std::unique_ptr<Workers> workers(threads > 0 ? new Workers(threads) : nullptr);
            PgsSolver solver;
            solver.use_workers(workers.get());
            std::vector<RigidBody> bodies = start;
            std::vector<double> l(velocity.lambda_exp.data(),
                                  velocity.lambda_exp.data() + velocity.lambda_exp.size());
            std::vector<double> p(static_cast<std::size_t>(report.position.mlcp.row_count()));
            SweepResult result;
            SweepResult position_result;
            if (both) {
              solver.solve_both(velocity.mlcp, l.data(), {sweeps, 0.0, record}, result,
                                report.position.mlcp, p.data(), {3, 0.0, false}, position_result,
                                {}, &bodies);
            } else {
              solver.solve(velocity.mlcp, l.data(), {sweeps, 0.0, record}, result, {}, &bodies);
            }
            CHECK(bytes_of(l.data(), l.size()) == expected_lambda);
            CHECK(wrenches_of(bodies) == expected_wrenches);
            // the last sweep did add them where the sweeps ran in parts: the check can fail
            if (both) {
              CHECK(solver.swept_side_by_side() == (!record && sweeps > 1));
            } else {
              CHECK((solver.swept_on_threads() || solver.swept_in_lanes()) ==
                    (!record && (threads > 0 || sweeps > 1)));
            }
          }
        }
      }
    }
  }

  TEST_CASE("two MLCPs solved side by side give each one's λ, and B λ, bit for bit") {
    // solve_both sweeps a step's velocity and position MLCPs at once (pgs_solver.h), each in
    // its own rows' order: both λ must be those of two solves one after the other on one
    // thread, and velocity_change() the second's — on one thread (four lanes), on 2 and 3
    // threads, with the pitfall clamp-increment, from a position λ that is not zero (its
    // a = B λ pass then runs in the lanes), and with a few boxes listed far from their
    // neighbours (lanes that wait on other threads). A recorded second solve is not swept side
    // by side (its residual is measured after each sweep), and gives the same λ.
    Scene swapped = builtin_scene("pyramid:20");
    std::swap(swapped.bodies[3], swapped.bodies[150]);
    std::swap(swapped.bodies[40], swapped.bodies[120]);
    for (const int which : {0, 1, 2, 3}) {
      const WorldReport report =
          which == 3 ? report_after(10, swapped) : report_after(which == 0 ? 3 : 60);
      const StepReport& velocity = report.velocity;
      StepReport position = report.position;
      REQUIRE(position.mlcp.row_count() >= 512);  // enough rows to be swept in parts
      if (which == 2) position.lambda_exp[position.lambda_exp.size() / 2] = 0.25;
      for (const bool clamped : {false, true}) {
        Pitfalls pitfalls;
        if (clamped) pitfalls.add(Pitfall::clamp_increment);
        PgsSolver one;
        const std::vector<unsigned char> expected_velocity = solved(one, velocity, 8, pitfalls);
        const std::vector<unsigned char> expected_position = solved(one, position, 3, pitfalls);
        for (const int threads : {0, 2, 3}) {
          CAPTURE(which);
          CAPTURE(clamped);
          CAPTURE(threads);
          for (const int sweeps : {3, -1}) {
            const SideBySide both =
                solved_side_by_side(threads, velocity, position, sweeps, pitfalls);
            CHECK(both.velocity == expected_velocity);
            CHECK(both.position == expected_position);
            CHECK(both.side_by_side == (sweeps > 0));  // side by side: the check can fail
            bool same_change = true;
            for (int b = 0; b < position.mlcp.body_count(); ++b) {
              same_change = same_change && both.velocity_change[b] == one.velocity_change(b);
            }
            CHECK(same_change);
          }
        }
      }
    }
  }

  TEST_CASE("PGS swept on 2 and 3 threads gives the one-thread λ bit for bit") {
    // The threads' order keeps every body's sequence of updates (pgs_solver.h): λ must be
    // identical, not close. Two moments of the pyramid: early (landing) and settled.
    for (const int steps : {3, 60}) {
      const StepReport step = mlcp_after(steps);
      REQUIRE(step.mlcp.row_count() >= 1000);
      PgsSolver one;
      const std::vector<unsigned char> expected = solved(one, step, 8);
      CHECK_FALSE(one.swept_on_threads());
      for (const int threads : {2, 3}) {
        CAPTURE(steps);
        CAPTURE(threads);
        const OnThreads plain = solved_on_threads(threads, step, 8);
        CHECK(plain.lambda == expected);
        CHECK(plain.swept_on_threads);  // the threads did sweep: the check can fail
        // the pitfall clamp-increment sweeps on threads too, and keeps its own numbers
        PgsSolver one_clamped;
        Pitfalls clamp;
        clamp.add(Pitfall::clamp_increment);
        const OnThreads clamped = solved_on_threads(threads, step, 8, clamp);
        CHECK(clamped.lambda == solved(one_clamped, step, 8, clamp));
        CHECK(clamped.swept_on_threads);
      }
    }
  }

  TEST_CASE("PGS from λ = 0 on threads, its a = B λ pass skipped, gives the one-thread λ") {
    // Split impulse's position MLCP is solved from λ = 0, where the threads skip the pass that
    // makes a = B λ (it adds nothing). λ must be one thread's bit for bit; so must it from a λ
    // that is zero but for one row (near the end: the pass is needed) and from the velocity
    // MLCP's λ all zero.
    const WorldReport report = report_after(60);
    StepReport position = report.position;
    REQUIRE(position.mlcp.row_count() >= 1000);
    REQUIRE(position.lambda_exp.isZero(0.0));
    StepReport one_nonzero = position;
    one_nonzero.lambda_exp[position.lambda_exp.size() - 5] = 0.25;
    StepReport velocity_from_zero = report.velocity;
    velocity_from_zero.lambda_exp.setZero();
    for (const StepReport* step : {&position, &one_nonzero, &velocity_from_zero}) {
      for (const int sweeps : {1, 3}) {
        PgsSolver one;
        const std::vector<unsigned char> expected = solved(one, *step, sweeps);
        for (const int threads : {2, 3}) {
          CAPTURE(step == &position ? "position" : step == &one_nonzero ? "one row" : "velocity");
          CAPTURE(sweeps);
          CAPTURE(threads);
          const OnThreads on_threads = solved_on_threads(threads, *step, sweeps);
          CHECK(on_threads.lambda == expected);
          CHECK(on_threads.swept_on_threads);
        }
      }
    }
  }

  TEST_CASE("rows in no order of place are swept on one thread, to the same λ") {
    // The pyramid's boxes listed in a shuffled order: a box's rows then share bodies with rows
    // all over the order, the threads would wait at nearly every group, and the solver keeps to
    // one thread.
    Scene shuffled = builtin_scene("pyramid:20");
    std::mt19937 rng(19);
    // the ground stays first
    std::shuffle(shuffled.bodies.begin() + 1, shuffled.bodies.end(), rng);
    const StepReport step = mlcp_after(30, shuffled);
    REQUIRE(step.mlcp.row_count() >= 1000);
    const OnThreads on_threads = solved_on_threads(2, step, 8);
    PgsSolver one;
    CHECK(on_threads.lambda == solved(one, step, 8));
    CHECK_FALSE(on_threads.swept_on_threads);
    CHECK_FALSE(one.swept_in_lanes());  // nor in two lanes
  }

  TEST_CASE("a few boxes listed far from their neighbours: the threads' λ is one thread's") {
    // A few of the pyramid's boxes swapped with others far away in the list: their rows then
    // share bodies with runs that are not next to theirs, so the two lanes of a thread can both
    // wait, each on a run of another thread (pgs_solver.h). A thread that then waited on one of
    // them alone could wait forever (that run waiting, in turn, on the thread's other lane); the
    // lanes must keep looking at both. Few enough swaps that the plan still sweeps on threads.
    int on_threads_count = 0;
    for (const unsigned seed : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u}) {
      for (const int swaps : {1, 2, 3}) {
        Scene scene = builtin_scene("pyramid:20");
        std::mt19937 rng(seed);
        std::uniform_int_distribution<std::size_t> box(1, scene.bodies.size() - 1);
        for (int k = 0; k < swaps; ++k) std::swap(scene.bodies[box(rng)], scene.bodies[box(rng)]);
        const StepReport step = mlcp_after(10, scene);
        PgsSolver one;
        const std::vector<unsigned char> expected = solved(one, step, 8);
        for (const int threads : {2, 3}) {
          CAPTURE(seed);
          CAPTURE(swaps);
          CAPTURE(threads);
          const OnThreads on_threads = solved_on_threads(threads, step, 8);
          CHECK(on_threads.lambda == expected);
          if (on_threads.swept_on_threads) ++on_threads_count;
        }
      }
    }
    CHECK(on_threads_count >= 24);  // most of the 48 solves did go on threads: the check can fail
    MESSAGE("solves on threads: " << on_threads_count << " of 48");
  }
}
