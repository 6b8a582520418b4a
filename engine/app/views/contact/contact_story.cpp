#include "app/views/contact/contact_story.h"

#include "language/language.h"

namespace lamina::view {

Fig4Moment fig4_moment(const WorldReport& report, int body, bool touched) {
  int points = 0, carrying = 0;
  for (const ContactPair& pair : report.pairs) {
    if (pair.bodies.first != body && pair.bodies.second != body) continue;
    for (int k = 0; k < pair.count; ++k) {
      ++points;
      if (pair.contacts[k].lambda_normal > 0.0) ++carrying;
    }
  }
  if (points == 0) return Fig4Moment::no_contact;
  if (!touched) return Fig4Moment::first_contact;
  if (carrying < 2) return Fig4Moment::one_point;
  const RigidBody& b = report.bodies.at(static_cast<std::size_t>(body));
  const bool resting = b.v.norm() < resting_speed && b.angular_velocity.norm() < resting_speed;
  return resting ? Fig4Moment::at_rest : Fig4Moment::two_points;
}

const char* figure_of(Fig4Moment moment) {
  switch (moment) {
    case Fig4Moment::no_contact: return "";
    case Fig4Moment::first_contact: return tr("Fig 4-2");
    case Fig4Moment::one_point: return tr("Fig 4-3");
    case Fig4Moment::two_points: return tr("Fig 4-4");
    case Fig4Moment::at_rest: return tr("Fig 4-5");
  }
  return "";
}

}  // namespace lamina::view
