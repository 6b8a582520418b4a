// Chapter 4's collision detection (beyond the text, which omits it): the deepest point of each
// pair type against analytic answers, the separating axis, touching and ties (the broad phase:
// test_broad_phase.cpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <random>
#include <vector>

#include "contact/contact_cache.h"
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
// The corners of a box at a pose, world frame.
std::array<Vec2, 4> core_vertices(const Shape& box, const Pose2& p) {
  const Convex core = core_of(box, p);
  return {core.vertices[0], core.vertices[1], core.vertices[2], core.vertices[3]};
}

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

  TEST_CASE("box–box's separating axes agree with GJK/EPA on random poses: depth and normal") {
    // The fast path and the general one on the same pairs, the box as a 4-vertex polygon. Both
    // measure the least penetration over the boxes' face normals (in 2D EPA's answer is a face
    // normal of one of them): they agree to the rounding of a few dot products. Pairs whose two
    // best axes are within 1e-6 of each other may pick either normal: only their depths count.
    std::mt19937 rng(20);
    std::uniform_real_distribution<double> half(0.05, 1.5), angle(-M_PI, M_PI), at(-1.0, 1.0);
    const TieRule first{false};  // the deepest vertex itself, no midpoint
    int compared = 0, normals = 0, shallow = 0;
    for (int k = 0; k < 5000; ++k) {
      const Shape a = Shape::box(half(rng), half(rng));
      const Shape b = Shape::box(half(rng), half(rng));
      const Pose2 pa = pose(at(rng), at(rng), angle(rng));
      const Pose2 pb = pose(at(rng), at(rng), angle(rng));
      const std::optional<Collision> fast = collide_boxes(a, pa, b, pb, none, first);
      const Shape qa = Shape::polygon({{-a.half_extents.x(), -a.half_extents.y()},
                                       {a.half_extents.x(), -a.half_extents.y()},
                                       {a.half_extents.x(), a.half_extents.y()},
                                       {-a.half_extents.x(), a.half_extents.y()}});
      const Shape qb = Shape::polygon({{-b.half_extents.x(), -b.half_extents.y()},
                                       {b.half_extents.x(), -b.half_extents.y()},
                                       {b.half_extents.x(), b.half_extents.y()},
                                       {-b.half_extents.x(), b.half_extents.y()}});
      const std::optional<Collision> general = collide_convex(qa, pa, qb, pb, none, first);
      REQUIRE(fast.has_value() == general.has_value());
      if (!fast) continue;
      ++compared;
      CHECK(general->depth == doctest::Approx(fast->depth).epsilon(1e-9).scale(1.0));
      // EPA's own depth, the least move apart, equals the deepest point's while the overlap is
      // shallower than half the smaller box. Deeper, a long box can cross the other with only a
      // shallow corner inside it, and that corner is the deepest point both paths return
      // (Fig 4-2's point lies inside the other body), not the least move apart.
      const double smallest = std::min({a.half_extents.minCoeff(), b.half_extents.minCoeff()});
      const Convex ca = core_of(a, pa), cb = core_of(b, pb);
      const EpaResult e = epa(ca, cb, gjk(ca, cb));
      if (e.depth < 0.5 * smallest) {
        CHECK(e.depth == doctest::Approx(fast->depth).epsilon(1e-9).scale(1.0));
        ++shallow;
      }
      // the second-best axis of the box pair, to tell a clear normal from a tie
      const Vec2 n = fast->normal;
      double runner_up = std::numeric_limits<double>::infinity();
      for (const Vec2& axis : {Vec2(pa.R.col(0)), Vec2(pa.R.col(1)), Vec2(pb.R.col(0)), Vec2(pb.R.col(1))}) {
        if (std::abs(std::abs(axis.dot(n)) - 1.0) < 1e-12) continue;
        double lo = 1e300, hi = -1e300, lo2 = 1e300, hi2 = -1e300;
        for (const Vec2& v : core_vertices(a, pa)) { lo = std::min(lo, axis.dot(v)); hi = std::max(hi, axis.dot(v)); }
        for (const Vec2& v : core_vertices(b, pb)) { lo2 = std::min(lo2, axis.dot(v)); hi2 = std::max(hi2, axis.dot(v)); }
        runner_up = std::min(runner_up, std::min(hi, hi2) - std::max(lo, lo2));
      }
      if (runner_up - fast->depth < 1e-6) continue;
      ++normals;
      CHECK((general->normal - fast->normal).norm() <= 1e-9);
    }
    CHECK(compared > 1000);  // the poses overlap often enough for the comparison to mean something
    CHECK(normals > 900);
    CHECK(shallow > 200);
  }

  TEST_CASE("a hexagon resting on the ground: both bottom corners tie, the first contact is their midpoint") {
    std::vector<Vec2> hexagon;
    for (int k = 0; k < 6; ++k) hexagon.push_back(0.5 * Vec2(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)));
    const Shape hex = Shape::polygon(hexagon);
    const Shape ground = Shape::box(5.0, 0.5);
    // Resting on the edge between vertices 4 and 5 (at 240° and 300°), sunk 0.01 m: the flat
    // bottom lies √3/4 below the centre.
    const double apothem = 0.5 * std::sqrt(3.0) / 2.0;
    const Pose2 at = pose(0.2, apothem - 0.01);
    const std::optional<Collision> first = collide(ground, pose(0.0, -0.5), hex, at, none, tie);
    check_collision(first, Vec2(0.0, 1.0), 0.01, Vec2(0.2, -0.01), exact);
    // With one of the bottom corners cached, the other one.
    CachedPoints cached;
    cached.points[0] = at.to_world(hexagon[4]);
    cached.count = 1;
    const std::optional<Collision> second = collide(ground, pose(0.0, -0.5), hex, at, cached, tie);
    check_collision(second, Vec2(0.0, 1.0), 0.01, at.to_world(hexagon[5]), exact);
  }

  TEST_CASE("a capsule lying on the ground: the normal up, the depth ρ − height, both caps tie") {
    const Shape capsule = Shape::capsule(0.25, 1.0);
    const Shape ground = Shape::box(5.0, 0.5);
    const Pose2 at = pose(-0.3, 0.25 - 0.02);  // sunk 0.02 m
    const std::optional<Collision> c = collide(ground, pose(0.0, -0.5), capsule, at, none, tie);
    check_collision(c, Vec2(0.0, 1.0), 0.02, Vec2(-0.3, -0.02), exact);
    // Tilted by 0.1 rad with its lower cap sunk 0.02 m: that cap's lowest point.
    const double lift = 0.5 * std::sin(0.1);
    const Pose2 tilted = pose(0.0, 0.25 - 0.02 + lift, 0.1);
    const std::optional<Collision> t = collide(ground, pose(0.0, -0.5), capsule, tilted, none, tie);
    check_collision(t, Vec2(0.0, 1.0), 0.02, Vec2(-0.5 * std::cos(0.1), -0.02), exact);
  }

  TEST_CASE("a triangle corner in a capsule's side: the capsule's side is the reference") {
    // A capsule along x at the origin, radius 0.3; a triangle pointing down with its tip 0.05 m
    // into the capsule's top side (y = 0.3): n from the capsule (body 1) up to the triangle.
    const Shape capsule = Shape::capsule(0.3, 2.0);
    const Shape tip = Shape::polygon({{0.0, -0.4}, {0.4, 0.2}, {-0.4, 0.2}});
    const Pose2 tip_pose = pose(0.1, 0.65);  // tip at y = 0.25
    const std::optional<Collision> c = collide(capsule, pose(0.0, 0.0), tip, tip_pose, none, tie);
    check_collision(c, Vec2(0.0, 1.0), 0.05, Vec2(0.1, 0.25), exact);
    CHECK(c->reference == 0);
  }

  TEST_CASE("a circle against a polygon: face region and corner region by GJK") {
    const Shape square = Shape::polygon({{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});
    const Shape ball = Shape::circle(0.25);
    // Over the top face, 0.05 m in: n up, the ball's lowest point.
    const std::optional<Collision> face = collide(square, pose(0.0, 0.0), ball, pose(0.2, 0.7), none, tie);
    check_collision(face, Vec2(0.0, 1.0), 0.05, Vec2(0.2, 0.45), exact);
    // Beyond the corner (0.5, 0.5) along the diagonal, 0.05 m in: n along the diagonal.
    const Vec2 d = Vec2(1.0, 1.0).normalized();
    const Vec2 centre = Vec2(0.5, 0.5) + 0.2 * d;
    const std::optional<Collision> corner =
        collide(square, pose(0.0, 0.0), ball, pose(centre.x(), centre.y()), none, tie);
    check_collision(corner, d, 0.05, centre - 0.25 * d, exact);
    // The same with the ball as body 1: n turns round.
    const std::optional<Collision> swapped =
        collide(ball, pose(centre.x(), centre.y()), square, pose(0.0, 0.0), none, tie);
    check_collision(swapped, -d, 0.05, Vec2(0.5, 0.5), 1e-9);
  }

  TEST_CASE("polygons apart by more than nothing are not in contact; two capsules crossed are") {
    const Shape tri = Shape::polygon({{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}});
    CHECK_FALSE(collide(tri, pose(0.0, 0.0), tri, pose(1.0 + 1e-9, 0.0), none, tie));
    const Shape rod = Shape::capsule(0.1, 2.0);
    const std::optional<Collision> x = collide(rod, pose(0.0, 0.0), rod, pose(0.0, 0.15, M_PI / 2), none, tie);
    // Crossed at right angles: the cores cross, and the least move apart lifts rod 2 until its
    // lower cap's centre (at y = 0.15 − 1 = −0.85) is 0.2 (both radii) above rod 1's core:
    // 1.05 up (sideways it would have to clear rod 1's whole length, 1.2).
    REQUIRE(x);
    CHECK(x->depth == doctest::Approx(1.05).epsilon(1e-9));
    CHECK((x->normal - Vec2(0.0, 1.0)).norm() <= 1e-9);
  }

  TEST_CASE("a run of the narrow phase that starts mid-way finds its pairs' cached points") {
    // Three kept pairs, (0, 1), (0, 2), (1, 2): a cursor for a pair starts at the first kept
    // pair not before it (exact indices: the pairs are sorted by (body 1, body 2)), and the
    // cached points found from there are the pair's own.
    const std::vector<Shape> shapes{Shape::box(5.0, 0.5), Shape::box(0.5, 0.5),
                                    Shape::box(0.5, 0.5)};
    const std::vector<Material> materials(3);
    const std::vector<Pose2> poses{Pose2{Vec2(0.0, -0.5)}, Pose2{Vec2(-1.0, 0.5)},
                                   Pose2{Vec2(1.0, 0.5)}};
    Collision touch;
    touch.point = Vec2(0.0, 0.0);
    ContactCache cache;
    cache.update({FreshCollision{BodyPair{0, 1}, touch}, FreshCollision{BodyPair{0, 2}, touch},
                  FreshCollision{BodyPair{1, 2}, touch}},
                 {}, poses, shapes, materials, CacheSettings{});
    REQUIRE(cache.pairs().size() == 3);
    CHECK(cache.cursor_at(BodyPair{0, 1}) == 0);
    CHECK(cache.cursor_at(BodyPair{0, 2}) == 1);
    CHECK(cache.cursor_at(BodyPair{0, 3}) == 2);
    CHECK(cache.cursor_at(BodyPair{1, 2}) == 2);
    CHECK(cache.cursor_at(BodyPair{2, 3}) == 3);
    for (const BodyPair& pair : {BodyPair{0, 2}, BodyPair{1, 2}}) {
      size_t cursor = cache.cursor_at(pair);
      const ContactPair* kept = cache.find(pair, cursor);
      REQUIRE(kept != nullptr);
      CHECK(kept->bodies == pair);
      CHECK(cached_points(*kept, poses).count == 1);
    }
    size_t past = cache.cursor_at(BodyPair{0, 3});
    CHECK(cache.find(BodyPair{0, 3}, past) == nullptr);  // not kept
  }
}
