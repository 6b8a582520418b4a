// Chapter 4's collision detection (beyond the text, which omits it): the deepest point of each
// pair type against analytic answers, the separating axis, touching, ties, and the broad phase.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "contact/broad_phase.h"
#include "contact/narrow_phase.h"

using namespace lamina;

namespace {

// Geometry here is a few additions and rotations of exact inputs: answers agree to rounding.
constexpr double exact = 1e-12;  // in m

Pose2 pose(double x, double y, double angle = 0.0) {
  Pose2 p;
  p.x = Vec2(x, y);
  p.R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return p;
}

const CachedPoints none{};
const TieRule tie;  // the cache's default: ties broken within 5e-4 m

// A contact with this normal (body 1 → body 2), depth and deepest point, each within `tolerance`.
void check_collision(const std::optional<Collision>& c, const Vec2& normal, double depth,
                     const Vec2& point, double tolerance) {
  REQUIRE(c);
  CHECK(c->normal.isApprox(normal, tolerance));
  CHECK(c->depth == doctest::Approx(depth).epsilon(tolerance));
  CHECK((c->point - point).norm() <= tolerance);
}

}  // namespace

TEST_SUITE("Collision") {
  TEST_CASE("a box pushed into the ground by 0.1 m at one corner: depth, normal up, that corner") {
    const Shape ground = Shape::box(5.0, 0.5);
    const Shape box = Shape::box(0.5, 0.5);
    // Tilted by θ, the lowest corner (−h, −h) sits (h cos θ + h sin θ) below the centre.
    const double angle = 0.2;
    const double drop = 0.5 * std::cos(angle) + 0.5 * std::sin(angle);
    const Pose2 box_pose = pose(0.3, drop - 0.1, angle);
    const std::optional<Collision> c = collide(ground, pose(0.0, -0.5), box, box_pose, none, tie);
    // n from body 1 (ground) to body 2 (box)
    check_collision(c, Vec2(0.0, 1.0), 0.1, box_pose.to_world(Vec2(-0.5, -0.5)), exact);
    CHECK(c->reference == 0);
  }

  TEST_CASE("the normal always points from the first body to the second") {
    const Shape ground = Shape::box(5.0, 0.5);
    const Shape box = Shape::box(0.5, 0.5);
    const Pose2 box_pose = pose(0.0, 0.45, 0.1);
    const std::optional<Collision> forward = collide(ground, pose(0.0, -0.5), box, box_pose, none, tie);
    const std::optional<Collision> backward = collide(box, box_pose, ground, pose(0.0, -0.5), none, tie);
    REQUIRE(forward);
    REQUIRE(backward);
    CHECK(forward->normal.isApprox(-backward->normal, exact));
    CHECK(forward->depth == doctest::Approx(backward->depth).epsilon(exact));
    CHECK(forward->reference == 0);   // the ground's face in both orders
    CHECK(backward->reference == 1);
  }

  TEST_CASE("the separating axis test picks the axis of least penetration") {
    const Shape a = Shape::box(1.0, 1.0);
    const Shape b = Shape::box(0.5, 0.5);
    // b overlaps a's right face by 0.05 and its top face by 0.6: the x axis separates least.
    const std::optional<Collision> side = collide(a, pose(0, 0), b, pose(1.45, 0.9, 0.0), none, tie);
    REQUIRE(side);
    CHECK(side->normal.isApprox(Vec2(1.0, 0.0), exact));
    CHECK(side->depth == doctest::Approx(0.05).epsilon(exact));
    // Turned 90°, b's own faces are the candidates too: the answer does not change.
    const std::optional<Collision> turned =
        collide(a, pose(0, 0), b, pose(1.45, 0.9, M_PI / 2), none, tie);
    REQUIRE(turned);
    CHECK(turned->normal.isApprox(Vec2(1.0, 0.0), 1e-9));
    CHECK(turned->depth == doctest::Approx(0.05).epsilon(1e-9));
    // Apart along x by 1 mm: no contact.
    CHECK_FALSE(collide(a, pose(0, 0), b, pose(1.501, 0.9), none, tie));
  }

  TEST_CASE("a box corner poking into the other box's face uses that box as the reference") {
    const Shape small = Shape::box(0.5, 0.5);
    const Shape wall = Shape::box(0.5, 2.0);
    // Body 1 is a diamond whose right corner enters the wall (body 2) by 0.05 through its left face.
    const double reach = 0.5 * std::sqrt(2.0);
    const std::optional<Collision> c =
        collide(small, pose(0.0, 0.0, M_PI / 4), wall, pose(reach + 0.5 - 0.05, 0.0), none, tie);
    check_collision(c, Vec2(1.0, 0.0), 0.05, Vec2(reach, 0.0), 1e-9);  // still body 1 → body 2
    CHECK(c->reference == 1);
  }

  TEST_CASE("exactly touching shapes are in contact with depth 0") {
    const Shape ground = Shape::box(5.0, 0.5);
    const Shape box = Shape::box(0.5, 0.5);
    const Shape ball = Shape::circle(0.5);
    const std::optional<Collision> boxes = collide(ground, pose(0, -0.5), box, pose(0, 0.5), none, tie);
    REQUIRE(boxes);
    CHECK(boxes->depth == 0.0);
    const std::optional<Collision> ball_on_box =
        collide(ground, pose(0, -0.5), ball, pose(2.0, 0.5), none, tie);
    REQUIRE(ball_on_box);
    CHECK(ball_on_box->depth == 0.0);
    const std::optional<Collision> balls = collide(ball, pose(0, 0), ball, pose(1.0, 0.0), none, tie);
    REQUIRE(balls);
    CHECK(balls->depth == 0.0);
    // A hair apart is apart.
    CHECK_FALSE(collide(ground, pose(0, -0.5), box, pose(0, 0.5 + 1e-9), none, tie));
    CHECK_FALSE(collide(ball, pose(0, 0), ball, pose(1.0 + 1e-9, 0.0), none, tie));
  }

  TEST_CASE("equally deep corners: the midpoint on a first contact, else the one the cache lacks") {
    const Shape ground = Shape::box(5.0, 0.5);
    const Shape box = Shape::box(0.5, 0.5);
    const Pose2 flat = pose(1.0, 0.49);  // both bottom corners 0.01 deep
    const std::optional<Collision> first = collide(ground, pose(0, -0.5), box, flat, none, tie);
    REQUIRE(first);
    CHECK(first->point.isApprox(Vec2(1.0, -0.01), exact));  // midpoint: pushes straight up
    CHECK(first->depth == doctest::Approx(0.01).epsilon(exact));
    CachedPoints left;
    left.points[0] = Vec2(0.5, -0.005);
    left.count = 1;
    const std::optional<Collision> next = collide(ground, pose(0, -0.5), box, flat, left, tie);
    REQUIRE(next);
    CHECK(next->point.isApprox(Vec2(1.5, -0.01), exact));  // the right corner, farthest from it
  }

  TEST_CASE("a box resting half over another finds both ends of the overlap, one from each box") {
    const Shape box = Shape::box(0.5, 0.5);
    const Pose2 below = pose(0.0, 0.0);
    const Pose2 above = pose(0.5, 0.99);  // overlaps x ∈ [0, 0.5], 0.01 deep
    CachedPoints cached;
    cached.count = 1;
    // With the upper box's bottom-left corner cached, the other end is the lower box's corner.
    cached.points[0] = Vec2(0.0, 0.49);
    const std::optional<Collision> right = collide(box, below, box, above, cached, tie);
    REQUIRE(right);
    CHECK(right->point.isApprox(Vec2(0.5, 0.5), exact));
    CHECK(right->reference == 1);  // the upper box's bottom face
    CHECK(right->normal.isApprox(Vec2(0.0, 1.0), exact));
    // With that corner cached instead, the upper box's corner over the lower box is returned.
    cached.points[0] = Vec2(0.5, 0.495);
    const std::optional<Collision> left = collide(box, below, box, above, cached, tie);
    REQUIRE(left);
    CHECK(left->point.isApprox(Vec2(0.0, 0.49), exact));
    CHECK(left->reference == 0);
    CHECK(left->depth == doctest::Approx(0.01).epsilon(1e-9));
  }

  TEST_CASE("two long boxes crossing like a plus sign still report their overlap") {
    const Shape bar = Shape::box(2.0, 0.1);
    const std::optional<Collision> c =
        collide(bar, pose(0, 0), bar, pose(0, 0, M_PI / 2), none, tie);
    REQUIRE(c);  // no vertex of either is inside the other
    // The least push that separates them moves one bar its half length plus the other's half
    // thickness: 2 + 0.1 along either axis.
    CHECK(c->depth == doctest::Approx(2.1).epsilon(1e-9));
  }

  TEST_CASE("box–circle: face region, corner region and centre inside") {
    const Shape box = Shape::box(1.0, 0.5);
    const Shape ball = Shape::circle(0.25);
    // Above the top face, 0.05 deep: n = +y, the ball's lowest point.
    const std::optional<Collision> face = collide(box, pose(0, 0), ball, pose(0.3, 0.7), none, tie);
    check_collision(face, Vec2(0.0, 1.0), 0.05, Vec2(0.3, 0.45), exact);
    // Off the top-right corner along the diagonal: n along the diagonal, depth 0.25 − distance.
    const double d = 0.2 / std::sqrt(2.0);
    const std::optional<Collision> corner =
        collide(box, pose(0, 0), ball, pose(1.0 + d, 0.5 + d), none, tie);
    REQUIRE(corner);
    CHECK(corner->normal.isApprox(Vec2(1.0, 1.0).normalized(), exact));
    CHECK(corner->depth == doctest::Approx(0.05).epsilon(1e-9));
    // Centre inside, nearer the right face: leaves through it.
    const std::optional<Collision> inside = collide(box, pose(0, 0), ball, pose(0.9, 0.0), none, tie);
    REQUIRE(inside);
    CHECK(inside->normal.isApprox(Vec2(1.0, 0.0), exact));
    CHECK(inside->depth == doctest::Approx(0.35).epsilon(exact));
    // circle–box is the same contact with n turned round and the box as body 2.
    const std::optional<Collision> flipped = collide(ball, pose(0.3, 0.7), box, pose(0, 0), none, tie);
    check_collision(flipped, Vec2(0.0, -1.0), 0.05, face->point, exact);
    CHECK(flipped->reference == 1);
  }

  TEST_CASE("circle–circle: depth, normal along the centres, the second circle's deepest point") {
    const Shape a = Shape::circle(0.5);
    const Shape b = Shape::circle(0.25);
    check_collision(collide(a, pose(0, 0), b, pose(0.6, 0.0), none, tie), Vec2(1.0, 0.0), 0.15,
                    Vec2(0.35, 0.0), exact);
    const std::optional<Collision> same = collide(a, pose(0, 0), b, pose(0, 0), none, tie);
    REQUIRE(same);
    CHECK(same->normal == Vec2(0.0, 1.0));  // concentric: pushed up by convention
  }
}

TEST_SUITE("BroadPhase") {
  std::vector<BodyPair> brute_force(const std::vector<Aabb>& boxes) {
    std::vector<BodyPair> pairs;
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
      for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j) {
        if (boxes[i].overlaps(boxes[j])) pairs.push_back({i, j});
      }
    }
    return pairs;  // already sorted by (first, second)
  }

  TEST_CASE("sort and sweep finds exactly the overlapping pairs of random scenes, sorted") {
    std::mt19937 rng(20240501);
    std::uniform_real_distribution<double> where(0.0, 20.0);
    std::uniform_real_distribution<double> size(0.05, 1.5);
    for (int scene = 0; scene < 50; ++scene) {
      std::vector<Aabb> boxes(200);
      for (Aabb& box : boxes) {
        box.min = Vec2(where(rng), where(rng));
        box.max = box.min + Vec2(size(rng), size(rng));
      }
      // A few exactly touching and exactly equal boxes: touching counts as overlapping.
      boxes[1].min = Vec2(boxes[0].max.x(), boxes[0].min.y());
      boxes[1].max = boxes[1].min + Vec2(1.0, 1.0);
      boxes[3] = boxes[2];
      std::vector<int> order;
      std::vector<BodyPair> pairs;
      sort_and_sweep(boxes, order, pairs);
      const std::vector<BodyPair> expected = brute_force(boxes);
      CHECK(pairs == expected);
      CHECK(std::find(pairs.begin(), pairs.end(), BodyPair{0, 1}) != pairs.end());
    }
  }

  TEST_CASE("the pairs come out in body order whatever the boxes' positions") {
    // Bodies listed right to left: the sweep meets 2, 1, 0, but the pairs are (0,1), (1,2).
    const std::vector<Aabb> boxes{{Vec2(2.0, 0.0), Vec2(3.0, 1.0)},
                                  {Vec2(1.0, 0.0), Vec2(2.0, 1.0)},
                                  {Vec2(0.0, 0.0), Vec2(1.0, 1.0)}};
    std::vector<int> order;
    std::vector<BodyPair> pairs;
    sort_and_sweep(boxes, order, pairs);
    REQUIRE(pairs.size() == 2);
    CHECK(pairs[0] == BodyPair{0, 1});
    CHECK(pairs[1] == BodyPair{1, 2});
  }
}
