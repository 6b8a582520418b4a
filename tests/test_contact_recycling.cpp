// Contact recycling (contact/contact_cache.h, beyond the text; issue 19): a pair that holds all
// its points, whose last deepest point was re-found, and whose bodies moved relative to each
// other by at most recycle_distance and recycle_angle since, skips the narrow phase; its points
// are re-placed from their anchors and re-anchored. What it must keep: the points the narrow
// phase would have given (a resting box, recycled and not), a moving pair collided every step,
// and the text's method without it.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "contact/contact_cache.h"
#include "contact/solvers.h"
#include "contact/world.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

using namespace lamina;

namespace {

// A built-in scene (the ground, body 0, and a unit box, body 1) stepped by `pgs`, with
// recycling on or off.
World pgs_world(const Scene& scene, bool recycle) {
  Scene by_pgs = scene;
  by_pgs.solver = "pgs";
  WorldSettings settings = world_settings(by_pgs);
  settings.cache.recycle = recycle;
  return build_world(by_pgs, settings);
}

// A full, settled pair of a unit box (body 1) on the ground (body 0), found at `poses`.
ContactPair settled_pair(const std::vector<Pose2>& poses) {
  ContactPair pair;
  pair.bodies = BodyPair{0, 1};
  pair.capacity = 2;
  pair.count = 2;
  pair.settled = true;
  pair.found_at = relative_pose(poses[0], poses[1]);
  return pair;
}

Pose2 turned(const Pose2& pose, double angle) {
  Pose2 out = pose;
  out.R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return out;
}

}  // namespace

TEST_SUITE("ContactRecycling") {
  TEST_CASE("a full, settled pair is recycled within the distance and the angle, not past them") {
    // 10 % on either side of each limit, so that the test does not depend on how it is compared
    // (squared, ≤); each case moves body 2 in body 1's frame, whatever body 1 does in the world.
    // Limits of their own, unlike each other, so that one read for the other shows.
    CacheSettings settings;
    settings.recycle_distance = 2e-3;
    settings.recycle_angle = 5e-4;
    const std::vector<Pose2> found{Pose2{Vec2(0.0, -0.5)}, Pose2{Vec2(0.0, 0.5)}};
    const ContactPair pair = settled_pair(found);
    CHECK(recyclable(pair, found, settings));
    for (const double share : {0.9, 1.1}) {
      CAPTURE(share);
      std::vector<Pose2> moved = found;
      moved[1].x += Vec2(0.6, 0.8) * (share * settings.recycle_distance);  // a unit direction
      CHECK(recyclable(pair, moved, settings) == (share < 1.0));
      std::vector<Pose2> turned_pair = found;
      // the chord of a turn by θ is 2 sin(θ/2): θ from the chord the limit allows
      const double angle = 2.0 * std::asin(share * settings.recycle_angle / 2.0);
      turned_pair[1] = turned(found[1], angle);
      CHECK(recyclable(pair, turned_pair, settings) == (share < 1.0));
    }
    // both bodies moved 3 m and turned half a radian together: nothing moved relative to each
    // other (body 2 still 1 m above body 1 in body 1's frame, not turned from it)
    std::vector<Pose2> together(2);
    together[0] = turned(Pose2{Vec2(3.0, 0.5)}, 0.5);
    together[1] = Pose2{together[0].to_world(Vec2(0.0, 1.0)), together[0].R};
    CHECK(recyclable(pair, together, settings));
  }

  TEST_CASE("a pair that is not full, not settled, or with recycling off is collided") {
    const std::vector<Pose2> poses{Pose2{Vec2(0.0, -0.5)}, Pose2{Vec2(0.0, 0.5)}};
    CacheSettings settings;
    ContactPair one = settled_pair(poses);
    one.count = 1;  // a second point may still come: only the narrow phase finds it
    CHECK_FALSE(recyclable(one, poses, settings));
    ContactPair unsettled = settled_pair(poses);
    unsettled.settled = false;  // its last deepest point was a new one: the next may be too
    CHECK_FALSE(recyclable(unsettled, poses, settings));
    settings.recycle = false;
    CHECK_FALSE(recyclable(settled_pair(poses), poses, settings));
  }

  TEST_CASE("a resting box's recycled points are those the narrow phase re-finds") {
    // The same box landing on a corner (turned 0.3 rad, from 2 m), stepped with recycling and
    // without: once at rest every step of the first keeps its two points without the narrow
    // phase (both kept), every step of the second re-finds one of them. The corners slid on
    // the ground as the box fell flat, so the ground's anchors lag behind them until re-anchored.
    // The two runs' boxes end 4.5e-10 m apart (measured: the steps that recycled round their
    // sums in another order), so each point is compared from its own box's centre (1e-10 m),
    // and each must be a bottom corner to rounding (1e-12 m), as the narrow phase places it.
    const Scene landing = builtin_scene("box-on-ground-tilted");
    World recycled = pgs_world(landing, true);
    World collided = pgs_world(landing, false);
    for (int k = 0; k < 300; ++k) {
      recycled.step();
      collided.step();
    }
    const std::vector<ContactInfo> a = recycled.contacts();
    const std::vector<ContactInfo> b = collided.contacts();
    REQUIRE(a.size() == 2);
    REQUIRE(b.size() == 2);
    int refound = 0;
    const RigidBody& box_a = recycled.bodies()[1];
    const RigidBody& box_b = collided.bodies()[1];
    MESSAGE("box apart by " << (box_a.x - box_b.x).norm() << " m");
    for (std::size_t k = 0; k < a.size(); ++k) {
      CAPTURE(k);
      CHECK(a[k].origin == ContactOrigin::kept);
      refound += b[k].origin == ContactOrigin::refound ? 1 : 0;
      // each point where the other run has it, from its own box's centre
      CHECK(((a[k].point - box_a.x) - (b[k].point - box_b.x)).norm() <= 1e-10);
      CHECK(std::abs(a[k].separation - b[k].separation) <= 1e-12);
      CHECK(std::abs(a[k].lambda_normal - b[k].lambda_normal) <= 1e-9);
      // the bottom corners, ±0.5 from the centre along x, exactly as the narrow phase places them
      const Vec3 local = box_a.rotation.transpose() * (a[k].point - box_a.x);
      CHECK(std::abs(std::abs(local.x()) - 0.5) <= 1e-12);
    }
    CHECK(refound == 1);
  }

  TEST_CASE("a sliding box is collided every step: it moves past the distance in each") {
    // 1 m/s along the ground is 16.7 mm a step, seventeen times recycle_distance: each step's
    // deepest point is found afresh (re-found), never recycled; the box slows by μ g.
    Scene sliding = builtin_scene("box-on-ground-resting");
    for (BodyDescription& body : sliding.bodies) body.friction = 0.1;
    sliding.bodies[1].velocity = Vec2(1.0, 0.0);
    World world = pgs_world(sliding, true);
    for (int k = 0; k < 20; ++k) {
      world.step();
      if (k < 5) continue;  // landing: the second corner comes within a step or two
      int refound = 0;
      for (const ContactInfo& c : world.contacts()) refound += c.origin == ContactOrigin::refound;
      CAPTURE(k);
      CHECK(refound == 1);  // the deepest corner; the other point kept, as without recycling
    }
  }

  TEST_CASE("the text's method never recycles; pgs and the chapter-6 methods built on it do") {
    CHECK_FALSE(with_solver(WorldSettings(), "text").cache.recycle);
    CHECK(with_solver(WorldSettings(), "pgs").cache.recycle);
  }

  TEST_CASE("a negative or non-finite recycling limit is refused, naming it") {
    CacheSettings bad;
    bad.recycle_distance = -1e-3;
    CHECK_THROWS_WITH_AS(validate(bad), doctest::Contains("recycle_distance"),
                         std::invalid_argument);
    CacheSettings nan;
    nan.recycle_angle = std::nan("");
    CHECK_THROWS_WITH_AS(validate(nan), doctest::Contains("recycle_angle"), std::invalid_argument);
  }
}
