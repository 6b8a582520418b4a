#include "contact/world_report.h"

namespace lamina {

std::vector<ContactInfo> contact_infos(const std::vector<ContactPair>& pairs) {
  std::vector<ContactInfo> infos;
  std::size_t count = 0;
  for (const ContactPair& pair : pairs) count += static_cast<std::size_t>(pair.count);
  infos.reserve(count);  // one allocation (a pyramid's thousand contacts grew it ten times)
  for (const ContactPair& pair : pairs) {
    for (int k = 0; k < pair.count; ++k) {
      const Contact& c = pair.contacts[k];
      infos.push_back(ContactInfo{pair.bodies, lift(c.point), lift(c.normal), c.separation,
                                  !c.fresh(), c.lambda_normal, c.lambda_tangent, c.origin});
    }
  }
  return infos;
}

std::vector<ContactInfo> WorldReport::contacts() const { return contact_infos(pairs); }

}  // namespace lamina
