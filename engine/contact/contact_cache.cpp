#include "contact/contact_cache.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "kinematics/require.h"

namespace lamina {
namespace {

// A re-anchored reference point off its body by more than this has left the surface.
constexpr double surface_tolerance = 1e-9;  // in m

ContactPair new_pair(const BodyPair& bodies, const std::vector<Shape>& shapes,
                     const std::vector<Material>& materials) {
  ContactPair pair;
  pair.bodies = bodies;
  pair.friction = combined_friction(materials[bodies.first], materials[bodies.second]);
  pair.restitution = combined_restitution(materials[bodies.first], materials[bodies.second]);
  // Two points hold a face or a capsule's side flat; a circle touches at one.
  pair.capacity = shapes[bodies.first].is_circle() || shapes[bodies.second].is_circle() ? 1 : 2;
  return pair;
}

// Step 1: re-place, re-measure, re-anchor or drop the cached points of a pair. A recycled pair's
// points are all re-anchored, as the narrow phase would have anchored them had it re-found them.
void refresh(ContactPair& pair, const std::vector<Pose2>& poses, const std::vector<Shape>& shapes,
             const CacheSettings& settings, bool recycled) {
  const Pose2& pose1 = poses[pair.bodies.first];
  const Pose2& pose2 = poses[pair.bodies.second];
  int kept = 0;
  for (int k = 0; k < pair.count; ++k) {
    Contact c = pair.contacts[k];
    place(c, pose1, pose2);
    c.origin = ContactOrigin::kept;
    if (recycled) {
      // within a hair of where the narrow phase found it on the surface: kept on it
      reanchor(c, pose1, pose2);
    } else if (settings.reanchor &&
               c.drift_squared > settings.drift_limit * settings.drift_limit) {
      // |drift| > drift_limit, compared squared (no square root for every kept point)
      reanchor(c, pose1, pose2);
      const int ref_body = c.reference == 0 ? pair.bodies.first : pair.bodies.second;
      if (!contains(shapes[ref_body], poses[ref_body], reference_point(c, pose1, pose2),
                    surface_tolerance)) {
        continue;
      }
    }
    if (c.separation > settings.keep_margin) continue;
    pair.contacts[kept++] = c;
  }
  pair.count = kept;
}

// Step 2: the fresh deepest point replaces a nearby cached point (inheriting its λ), is added,
// or replaces the cached point nearer to it when the pair is full. True when it was re-found.
bool merge(ContactPair& pair, Contact fresh, const CacheSettings& settings) {
  int nearest = -1;
  double nearest_distance = 0.0;
  for (int k = 0; k < pair.count; ++k) {
    const double d = (pair.contacts[k].point - fresh.point).norm();
    if (nearest < 0 || d < nearest_distance) {
      nearest = k;
      nearest_distance = d;
    }
  }
  const bool same_point =
      nearest >= 0 && (pair.capacity == 1 || nearest_distance <= settings.merge_distance);
  if (same_point) {
    fresh.lambda_normal = pair.contacts[nearest].lambda_normal;
    fresh.lambda_tangent = pair.contacts[nearest].lambda_tangent;
    fresh.origin = ContactOrigin::refound;
    pair.contacts[nearest] = fresh;
  } else if (pair.count < pair.capacity) {
    pair.contacts[pair.count++] = fresh;
  } else {
    pair.contacts[nearest] = fresh;
  }
  return same_point;
}

void require_margin(double value, const char* name) {
  require(std::isfinite(value) && value >= 0.0,
          std::string("cache settings: ") + name + " must be finite and ≥ 0, got " +
              std::to_string(value));
}

}  // namespace

void validate(const CacheSettings& s) {
  require_margin(s.keep_margin, "keep_margin");
  require_margin(s.merge_distance, "merge_distance");
  require_margin(s.drift_limit, "drift_limit");
  require_margin(s.ties.tolerance, "ties.tolerance");
  require_margin(s.recycle_distance, "recycle_distance");
  require_margin(s.recycle_angle, "recycle_angle");
}

size_t ContactCache::cursor_at(const BodyPair& bodies) const {
  return static_cast<size_t>(
      std::lower_bound(pairs_.begin(), pairs_.end(), bodies,
                       [](const ContactPair& pair, const BodyPair& b) { return pair.bodies < b; }) -
      pairs_.begin());
}

const ContactPair* ContactCache::find(const BodyPair& bodies, size_t& cursor) const {
  while (cursor < pairs_.size() && pairs_[cursor].bodies < bodies) ++cursor;
  if (cursor == pairs_.size() || !(pairs_[cursor].bodies == bodies)) return nullptr;
  return &pairs_[cursor];
}

CachedPoints cached_points(const ContactPair& pair, const std::vector<Pose2>& poses) {
  CachedPoints cached;
  for (int k = 0; k < pair.count; ++k) {
    cached.points[cached.count++] =
        placed_point(pair.contacts[k], poses[pair.bodies.first], poses[pair.bodies.second]);
  }
  return cached;
}

bool recyclable(const ContactPair& pair, const std::vector<Pose2>& poses,
                const CacheSettings& settings) {
  if (!settings.recycle || !pair.settled || pair.count < pair.capacity) return false;
  const RelativePose now = relative_pose(poses[pair.bodies.first], poses[pair.bodies.second]);
  // compared squared: no square root for every pair of a pile
  const double distance = settings.recycle_distance;
  const double angle = settings.recycle_angle;
  return (now.offset - pair.found_at.offset).squaredNorm() <= distance * distance &&
         (now.turn - pair.found_at.turn).squaredNorm() <= angle * angle;
}

void ContactCache::update(const std::vector<FreshCollision>& fresh,
                          const std::vector<unsigned char>& recycled,
                          const std::vector<Pose2>& poses,
                          const std::vector<Shape>& shapes, const std::vector<Material>& materials,
                          const CacheSettings& settings, Workers* workers) {
  // The cached pairs the merge takes: all of pairs_, or none with the cache off. (Cleared
  // instead, pairs_ would come back as next_ empty, and the join below would make every pair
  // anew before copying into it.)
  const std::size_t kept = settings.enabled ? pairs_.size() : 0;
  // Each run of the workers takes a run of the cached pairs and the fresh collisions of the
  // same bodies (both sorted by pair), and keeps its pairs in order; the runs are joined in
  // order. The longer of the two lists is cut into equal shares and the other at the same
  // pairs, so that a step whose pairs are mostly new (the first, the cache empty; every step
  // with the cache off) is cut as evenly as one whose pairs are mostly cached.
  const int runs = runs_on(workers);
  const bool by_cached = kept >= fresh.size();
  // where run t starts in each list: at its share of the longer, and at the first of the other
  // from the same pair on (the first run: at 0; after the last run: at the ends)
  const auto run_start = [&](int t) -> std::pair<std::size_t, std::size_t> {
    if (t == 0) return {0, 0};
    if (t == runs) return {kept, fresh.size()};
    if (by_cached) {
      const std::size_t cached = share_of(kept, t, runs).first;
      if (cached == kept) return {cached, fresh.size()};
      const auto found = std::lower_bound(
          fresh.begin(), fresh.end(), pairs_[cached].bodies,
          [](const FreshCollision& f, const BodyPair& b) { return f.bodies < b; });
      return {cached, static_cast<std::size_t>(found - fresh.begin())};
    }
    const std::size_t found = share_of(fresh.size(), t, runs).first;
    if (found == fresh.size()) return {kept, found};
    const auto cached = std::lower_bound(
        pairs_.begin(), pairs_.begin() + static_cast<std::ptrdiff_t>(kept), fresh[found].bodies,
        [](const ContactPair& c, const BodyPair& b) { return c.bodies < b; });
    return {static_cast<std::size_t>(cached - pairs_.begin()), found};
  };
  next_of_run_.resize(runs);
  const auto update_run = [&](int t) {
    const auto [first, first_found] = run_start(t);
    const auto [last, last_found] = run_start(t + 1);
    std::vector<ContactPair>& next = runs == 1 ? next_ : next_of_run_[t];
    next.clear();
    const auto at = [](const auto& list, std::size_t i) {
      return list.begin() + static_cast<std::ptrdiff_t>(i);
    };
    merge_run(at(pairs_, first), at(pairs_, last),
              recycled.empty() ? nullptr : recycled.data() + first, at(fresh, first_found),
              at(fresh, last_found), poses, shapes, materials, settings, next);
  };
  run_on(workers, update_run);
  if (runs > 1) join_runs(next_of_run_, next_, workers);
  pairs_.swap(next_);
}

void ContactCache::merge_run(std::vector<ContactPair>::const_iterator cached,
                             std::vector<ContactPair>::const_iterator cached_end,
                             const unsigned char* recycled,
                             std::vector<FreshCollision>::const_iterator found,
                             std::vector<FreshCollision>::const_iterator found_end,
                             const std::vector<Pose2>& poses, const std::vector<Shape>& shapes,
                             const std::vector<Material>& materials, const CacheSettings& settings,
                             std::vector<ContactPair>& next) const {
  // Walk the cached pairs and the fresh collisions together, both sorted by pair.
  while (cached != cached_end || found != found_end) {
    const bool take_cached =
        cached != cached_end && (found == found_end || !(found->bodies < cached->bodies));
    const bool take_fresh =
        found != found_end && (cached == cached_end || !(cached->bodies < found->bodies));
    ContactPair pair = take_cached ? *cached : new_pair(found->bodies, shapes, materials);
    if (take_cached) {
      const bool skipped = recycled != nullptr && *recycled++ != 0;
      refresh(pair, poses, shapes, settings, skipped);
      pair.recycled = skipped;
      // collided and not found, or no longer a candidate: no longer settled
      pair.settled = skipped;
      ++cached;
    }
    if (take_fresh) {
      const Pose2& pose1 = poses[pair.bodies.first];
      const Pose2& pose2 = poses[pair.bodies.second];
      pair.settled = merge(pair, make_contact(found->collision, pose1, pose2), settings);
      pair.recycled = false;
      pair.found_at = relative_pose(pose1, pose2);
      ++found;
    }
    if (pair.count > 0) next.push_back(pair);
  }
}

ContactRows ContactCache::rows(const std::vector<RigidBody>& bodies,
                               const ContactSettings& settings, const StepSettings& step,
                               std::vector<double>& lambda) {
  return ContactRows(pairs_, bodies, settings, step, lambda);
}

void ContactCache::store_lambdas(const double* lambda, Workers* workers) {
  store_contact_lambdas(pairs_, lambda, workers);
}

}  // namespace lamina
