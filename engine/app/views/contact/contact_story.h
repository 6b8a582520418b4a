// The text's Fig 4-2..4-5, told from what each World step solved for one body landing on the
// ground. The text's story: collision detection finds only the deepest point, corner a, where
// the engine pushes (Fig 4-2, 4-3); the body turns and corner b goes in while a is still in the
// cache, so both are solved together (Fig 4-4); the body comes to rest on the two (Fig 4-5).
// A step is told by the forces it solved, not by which points the cache holds: a cached point
// that carries nothing pushes nowhere.
#pragma once

#include "contact/world_report.h"

namespace lamina::view {

enum class Fig4Moment {
  no_contact,     // falling, or in the air between bounces
  first_contact,  // Fig 4-2: the first step with a contact, the deepest point
  one_point,      // Fig 4-3: one point carries the contact force, the body turns over it
  two_points,     // Fig 4-4: two points carry it, solved together
  at_rest         // Fig 4-5: at rest on two points
};

// |v| (m/s) and |ω| (rad/s) below this count as resting.
inline constexpr double resting_speed = 1e-2;

// The moment of step k for `body`: `touched` says whether an earlier step had a contact.
Fig4Moment fig4_moment(const WorldReport& report, int body, bool touched);

// "Fig 4-2", "Fig 4-3", ...; empty for no_contact.
const char* figure_of(Fig4Moment moment);

}  // namespace lamina::view
