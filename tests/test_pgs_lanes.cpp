// PGS's sweeps in two lanes on one thread (issue 19, pgs_solver.h): λ must be the row-by-row
// sweeps' bit for bit, with the parts' plan kept or made again, from the smallest MLCP swept in
// lanes on. The threads: test_pgs_threads.cpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "constraints/pgs_solver.h"
#include "parallel/workers.h"
#include "scene/builtin_scenes.h"
#include "support/pgs_support.h"

using namespace lamina;

TEST_SUITE("PGS in lanes") {
  TEST_CASE("PGS swept in two lanes on one thread gives the row-by-row sweeps' λ bit for bit") {
    // The lanes keep every body's sequence of updates, as the threads do (pgs_solver.h): λ must
    // be identical to the plain sweep's, row after row. Recording the sweeps forces the plain
    // sweep (it measures the residual after each), and recording never changes λ.
    for (const int steps : {3, 60}) {
      const StepReport step = mlcp_after(steps);
      REQUIRE(step.mlcp.row_count() >= 1000);
      for (const int sweeps : {2, 3, 8}) {
        for (const bool clamped : {false, true}) {
          CAPTURE(steps);
          CAPTURE(sweeps);
          CAPTURE(clamped);
          Pitfalls pitfalls;
          if (clamped) pitfalls.add(Pitfall::clamp_increment);
          PgsSolver row_by_row;
          std::vector<double> expected(step.lambda_exp.data(),
                                       step.lambda_exp.data() + step.lambda_exp.size());
          SweepResult recorded;
          row_by_row.solve(step.mlcp, expected.data(), {sweeps, 0.0, true}, recorded, pitfalls);
          CHECK_FALSE(row_by_row.swept_in_lanes());
          PgsSolver lanes;
          CHECK(solved(lanes, step, sweeps, pitfalls) ==
                bytes_of(expected.data(), expected.size()));
          CHECK(lanes.swept_in_lanes());  // the lanes did sweep: the check can fail
        }
      }
    }
  }

  TEST_CASE("a kept plan serves MLCPs whose groups are on the same bodies, and no others") {
    // A solver keeps the last two plans it made (part_plan.h). In its first step the same
    // pyramid with two boxes swapped in the list has as many groups and rows (the same boxes
    // touch), only other bodies in them: its plan must be made again. A step's position MLCP
    // (the contact rows alone, other rows in each group, the same bodies) and the settled
    // pyramid's (other rows: pairs with one point or two) are served by the plan of the same
    // bodies. Each λ must be a fresh solver's bit for bit.
    const WorldReport first = report_after(0);
    const StepReport& placed = first.velocity;
    Scene swapped_scene = builtin_scene("pyramid:20");
    std::swap(swapped_scene.bodies[10], swapped_scene.bodies[100]);
    const StepReport swapped = mlcp_after(0, swapped_scene);
    REQUIRE(swapped.mlcp.groups().size() == placed.mlcp.groups().size());
    REQUIRE(swapped.mlcp.row_count() == placed.mlcp.row_count());
    Scene twice_swapped_scene = swapped_scene;
    std::swap(twice_swapped_scene.bodies[20], twice_swapped_scene.bodies[150]);
    const StepReport twice_swapped = mlcp_after(0, twice_swapped_scene);
    const StepReport settled = mlcp_after(60);
    REQUIRE(settled.mlcp.row_count() != placed.mlcp.row_count());
    REQUIRE(first.position.mlcp.row_count() < placed.mlcp.row_count());
    PgsSolver kept;
    const auto solve_kept = [&](const StepReport& step, long plans_made) {
      PgsSolver fresh;
      CHECK(solved(kept, step, 8) == solved(fresh, step, 8));
      CHECK(kept.swept_in_lanes());  // the plan was used: the checks can fail
      CHECK(kept.plans_made() == plans_made);
    };
    solve_kept(placed, 1);
    solve_kept(first.position, 1);  // served by the velocity MLCP's plan
    solve_kept(placed, 1);
    solve_kept(swapped, 2);  // the same sizes, other bodies: made again
    solve_kept(placed, 2);  // the plan before it, kept beside it
    solve_kept(settled, 2);  // other rows, the same bodies
    solve_kept(twice_swapped, 3);  // made again, in place of the older (swapped's)
    solve_kept(swapped, 4);  // no longer among the last two
  }

  TEST_CASE("an MLCP of 48 rows or more is swept in two lanes, to the row-by-row λ; fewer, not") {
    // PgsSolver::lanes_min_rows: the lanes pay from about 48 rows (pgs_solver.h). A stack of 16
    // boxes has 48 rows (each pair two contact rows and a friction row) and is swept in lanes;
    // one of 14 (42 rows) is not. pyramid:10 (399 rows) is too small for threads
    // (threads_min_rows): given two, the solver sweeps it in two lanes on the calling thread.
    // The honeycomb of hexagon-pyramid (401 rows), whose groups wait on the other lane more often
    // than threads allow (part_plan.cpp), is swept in lanes too. λ must be the row-by-row
    // sweep's bit for bit in every case.
    struct Case {
      const char* scene;
      bool in_lanes;
      int threads;
    };
    for (const Case c : {Case{"vertical-stack:16", true, 1}, Case{"vertical-stack:14", false, 1},
                         Case{"pyramid:10", true, 2}, Case{"hexagon-pyramid", true, 1}}) {
      CAPTURE(c.scene);
      const StepReport step = mlcp_after(30, builtin_scene(c.scene));
      const int rows = step.mlcp.row_count();
      CAPTURE(rows);
      REQUIRE((rows >= PgsSolver::lanes_min_rows) == c.in_lanes);
      REQUIRE(rows < PgsSolver::threads_min_rows);
      PgsSolver row_by_row;
      std::vector<double> expected(step.lambda_exp.data(),
                                   step.lambda_exp.data() + step.lambda_exp.size());
      SweepResult recorded;
      row_by_row.solve(step.mlcp, expected.data(), {8, 0.0, true}, recorded);
      REQUIRE_FALSE(row_by_row.swept_in_lanes());
      Workers workers(c.threads);
      PgsSolver solver;
      solver.use_workers(&workers);
      CHECK(solved(solver, step, 8) == bytes_of(expected.data(), expected.size()));
      CHECK(solver.swept_in_lanes() == c.in_lanes);  // the lanes swept where they should
      CHECK_FALSE(solver.swept_on_threads());
    }
  }
}
