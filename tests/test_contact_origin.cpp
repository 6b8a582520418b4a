// Where each contact point of a step comes from (contact/contact.h, ContactOrigin; issue 23):
// new (this step's deepest point, no λ from before), re-found (this step's deepest point where a
// cached point was, warm-started from its λ), kept (a cached point re-placed from its anchors,
// eq. 5-12). The Fig 4-2..4-5 story in these words, and a resting pyramid that is all re-found
// and kept points, as a pyramid at rest must be.
#include <doctest/doctest.h>

#include <map>
#include <string>

#include "contact/world.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"
#include "trace/trace.h"

using namespace lamina;

namespace {

World scene_world(const std::string& name) {
  const Scene scene = builtin_scene(name);
  return build_world(scene, world_settings(scene));
}

}  // namespace

TEST_SUITE("ContactOrigin") {
  TEST_CASE("the names traces and explanations use") {
    CHECK(std::string(origin_name(ContactOrigin::fresh)) == "new");
    CHECK(std::string(origin_name(ContactOrigin::refound)) == "refound");
    CHECK(std::string(origin_name(ContactOrigin::kept)) == "kept");
  }

  TEST_CASE("a resting pyramid has no new points after 1 s: each is re-found or kept") {
    // The 20-row pyramid, placed touching, after 60 steps: nothing in it moves, so each pair's
    // deepest point would be found where a cached point already was (re-found, warm started)
    // and its other point re-placed from its anchors (kept); by its method, islands, whose
    // contact recycling skips the narrow phase for a full pair that barely moved, nearly every
    // point is kept. A new point would be a corner touching for the first time. Measured: 0 of
    // 1114 new (1 re-found, 1113 kept; without recycling 413 and 701). The bar: at most 1 %.
    World world = scene_world("pyramid");
    for (int k = 0; k < 60; ++k) world.step();
    std::map<ContactOrigin, int> count;
    for (const ContactInfo& c : world.contacts()) {
      ++count[c.origin];
      CHECK(c.cached == (c.origin == ContactOrigin::kept));  // the trace's "cached", kept as was
    }
    const int total = count[ContactOrigin::fresh] + count[ContactOrigin::refound] + count[ContactOrigin::kept];
    MESSAGE("resting pyramid at 1 s: " << count[ContactOrigin::fresh] << " new, "
            << count[ContactOrigin::refound] << " re-found, " << count[ContactOrigin::kept]
            << " kept of " << total);
    REQUIRE(total > 1000);
    CHECK(count[ContactOrigin::fresh] <= total / 100);
    CHECK(count[ContactOrigin::refound] > 0);
    CHECK(count[ContactOrigin::kept] > 0);
  }

  TEST_CASE("Fig 4-2..4-5: the first contact is new; the second corner is new beside a kept or re-found first") {
    // The tilted landing (box-on-ground-tilted): the first step with a contact has one point,
    // new (Fig 4-2). The first step with two points has the corner that landed second new, and
    // the first corner kept or re-found (Fig 4-4). In the trace, "origin" says the same.
    World world = scene_world("box-on-ground-tilted");
    const Scene scene = builtin_scene("box-on-ground-tilted");
    bool first_seen = false, second_seen = false;
    for (int k = 0; k < 120 && !second_seen; ++k) {
      world.step();
      const std::vector<ContactInfo> contacts = world.contacts();
      if (contacts.empty()) continue;
      const TraceStep record = trace_step(scene, world, k);
      if (!first_seen) {
        first_seen = true;
        REQUIRE(contacts.size() == 1);
        CHECK(contacts[0].origin == ContactOrigin::fresh);
        CHECK(record.contacts[0].origin == "new");
        continue;
      }
      if (contacts.size() == 2) {
        second_seen = true;
        const ContactInfo& a = contacts[0];  // the pair's first point: the corner that landed first
        const ContactInfo& b = contacts[1];
        CHECK(b.origin == ContactOrigin::fresh);
        CHECK((a.origin == ContactOrigin::kept || a.origin == ContactOrigin::refound));
        CHECK(record.contacts[1].origin == "new");
        CHECK(a.point.x() * b.point.x() < 0.0);  // opposite corners
      }
    }
    CHECK(first_seen);
    CHECK(second_seen);
  }
}
