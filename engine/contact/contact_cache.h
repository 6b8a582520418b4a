// The contact cache of chapter 4 (Fig 4-2..4-5) and chapter 5 (eq. 5-12).
//
// The narrow phase finds one point per pair per step, the deepest. A box resting on the ground
// needs two. The cache remembers last step's points in both bodies' frames and, every step:
//   1. re-places each cached point from its anchors (eq. 5-12) and re-measures C (eq. 4-1);
//      a point whose anchors slid apart by more than drift_limit is re-anchored, not dropped;
//      a point is dropped once C > keep_margin, or when re-anchoring moves it off the
//      reference body's surface (a box sliding off a ledge);
//   2. merges the fresh deepest point: within merge_distance of a cached point it replaces that
//      point and inherits its λ; otherwise it is added; a full pair keeps the fresh point and
//      the cached point farthest from it.
// A pair keeps at most two points: two convex shapes in the plane touch along at most one
// segment, and its two ends carry any load it can carry. A circle touches at one point, so a
// pair with a circle keeps one, and the fresh point always takes over its λ.
// Each cached point keeps last step's λ (normal and friction) as the PGS starting guess.
// Switched off, the cache holds only this step's fresh points, with λ = 0 (no warm start).
//
// Contact recycling (beyond the text): a pair that holds all the points it can keep, whose last
// deepest point was one it held already (re-found: the narrow phase had nothing new to give it),
// and whose two bodies moved relative to each other by at most recycle_distance and
// recycle_angle since then, is not collided again: its deepest point would again be one of its
// points, or within a hair of one. Its points are re-placed from their anchors (step 1) and
// re-anchored, as the narrow phase would have anchored them on re-finding them. A resting pile,
// whose pairs all hold two points, then skips the narrow phase almost everywhere.
#pragma once

#include <vector>

#include "contact/contact.h"
#include "contact/contact_rows.h"
#include "parallel/workers.h"

namespace lamina {

struct CacheSettings {
  bool enabled = true;          // keep points between steps and warm start from their λ
  double keep_margin = 0.01;    // a cached point is dropped once its separation C exceeds this, in m
  double merge_distance = 0.02; // a fresh point this close to a cached one replaces it, in m
  double drift_limit = 0.01;    // anchors that slid apart by more than this are re-anchored, in m
  bool reanchor = true;         // false: a cached point keeps its anchors however far they slide
                                // (the text, which keeps a point until C > keep_margin)
  TieRule ties;                 // how equally deep vertices are told apart (narrow_phase.h)
  bool recycle = true;          // a full pair that barely moved skips the narrow phase (false:
                                // the text, which finds every pair's deepest point every step)
  double recycle_distance = 1e-3;  // how far body 2 may move in body 1's frame, in m
  double recycle_angle = 1e-3;  // how far it may turn, in rad (the chord of its turn, ≈ the angle)
};

// Throws std::invalid_argument naming the first margin that is negative or not finite.
void validate(const CacheSettings& settings);

// The cached points of a pair re-placed at the current poses, for the narrow phase's ties.
CachedPoints cached_points(const ContactPair& pair, const std::vector<Pose2>& poses);

// Contact recycling: the pair holds all its points, settled, and its bodies barely moved
// relative to each other since the narrow phase last found a point of it (above), so the narrow
// phase skips it.
bool recyclable(const ContactPair& pair, const std::vector<Pose2>& poses,
                const CacheSettings& settings);

// The narrow phase's result for one pair.
struct FreshCollision {
  BodyPair bodies;      // the pair, body 1 < body 2
  Collision collision;  // its deepest point
};

class ContactCache {
 public:
  // The pairs with contacts, sorted by (body 1, body 2).
  const std::vector<ContactPair>& pairs() const { return pairs_; }

  // The kept pair of `bodies`, or nullptr when the cache holds none. Pairs are asked for in
  // sorted order: `cursor` walks the cache once, from 0 or from cursor_at(the first one asked).
  const ContactPair* find(const BodyPair& bodies, size_t& cursor) const;
  // Where a cursor asking first for `bodies` may start: the first kept pair not before it
  // (a run of the narrow phase that starts mid-way skips the pairs before it without reading
  // them one by one).
  size_t cursor_at(const BodyPair& bodies) const;

  // Steps 1 and 2 above. `fresh` must be sorted by pair; `recycled` holds, for each of pairs(),
  // whether the narrow phase recycled it (empty: none); materials give a new pair's μ and e.
  // With `workers`, each of their threads updates a run of the pairs (each pair's update is its
  // own) and the runs are joined in order.
  void update(const std::vector<FreshCollision>& fresh, const std::vector<unsigned char>& recycled,
              const std::vector<Pose2>& poses,
              const std::vector<Shape>& shapes, const std::vector<Material>& materials,
              const CacheSettings& settings, Workers* workers = nullptr);

  // The writer of its pairs' rows and of their warm-start λ into `lambda`, which records where
  // each pair's and each contact's rows went as it writes them (contact_rows.h, ContactRows):
  // Mlcp::assemble runs it.
  ContactRows rows(const std::vector<RigidBody>& bodies, const ContactSettings& settings,
                   const StepSettings& step, std::vector<double>& lambda);
  // Keeps each contact's solved λ, read from its rows, as its warm start for the next step (on
  // `workers`' threads if given).
  void store_lambdas(const double* lambda, Workers* workers = nullptr);

 private:
  // Steps 1 and 2 for the cached pairs [cached, cached_end), whether each was recycled (from
  // `recycled` on; nullptr: none), and the fresh collisions [found, found_end) of the same
  // bodies: the kept pairs appended to `next`, in order.
  void merge_run(std::vector<ContactPair>::const_iterator cached,
                 std::vector<ContactPair>::const_iterator cached_end, const unsigned char* recycled,
                 std::vector<FreshCollision>::const_iterator found,
                 std::vector<FreshCollision>::const_iterator found_end,
                 const std::vector<Pose2>& poses, const std::vector<Shape>& shapes,
                 const std::vector<Material>& materials, const CacheSettings& settings,
                 std::vector<ContactPair>& next) const;

  std::vector<ContactPair> pairs_;  // this step's pairs, sorted
  std::vector<ContactPair> next_;   // scratch for the update, kept to avoid allocation
  PerRun<std::vector<ContactPair>> next_of_run_;  // on threads: each run's pairs
};

}  // namespace lamina
