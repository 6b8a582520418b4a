#include "contact/world_report.h"

namespace lamina {

ContactInfo contact_info(const ContactPair& pair, int k) {
  const Contact& c = pair.contacts[k];
  return {pair.bodies, lift(c.point), lift(c.normal), c.separation, !c.fresh(), c.lambda_normal,
          c.lambda_tangent, c.origin};
}

std::size_t contact_count(const std::vector<ContactPair>& pairs) {
  std::size_t count = 0;
  for (const ContactPair& pair : pairs) count += static_cast<std::size_t>(pair.count);
  return count;
}

std::vector<ContactInfo> contact_infos(const std::vector<ContactPair>& pairs) {
  std::vector<ContactInfo> infos;
  infos.reserve(contact_count(pairs));  // one allocation (a pyramid's contacts grew it ten times)
  for (const ContactPair& pair : pairs) {
    for (int k = 0; k < pair.count; ++k) infos.push_back(contact_info(pair, k));
  }
  return infos;
}

std::vector<ContactInfo> WorldReport::contacts() const { return contact_infos(pairs); }

}  // namespace lamina
