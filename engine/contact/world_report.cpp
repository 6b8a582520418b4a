#include "contact/world_report.h"

namespace lamina {

Vec6 constraint_wrench(const StepReport& report, int body) {
  Vec6 wrench = Vec6::Zero();
  for (size_t i = 0; i < report.mlcp.rows.size(); ++i) {
    const ConstraintRow& row = report.mlcp.rows[i];
    for (int k = 0; k < 2; ++k) {
      // eq. 3-11: F_c = Jᵀ λ, body b's block
      if (row.Jmap[k] == body) wrench += report.solution.lambda[static_cast<Eigen::Index>(i)] * row.Jsp[k];
    }
  }
  return wrench;
}

std::vector<ContactInfo> contact_infos(const std::vector<ContactPair>& pairs) {
  std::vector<ContactInfo> infos;
  for (const ContactPair& pair : pairs) {
    for (int k = 0; k < pair.count; ++k) {
      const Contact& c = pair.contacts[k];
      infos.push_back(ContactInfo{pair.bodies, lift(c.point), lift(c.normal), c.separation,
                                  !c.fresh, c.lambda_normal, c.lambda_tangent});
    }
  }
  return infos;
}

}  // namespace lamina
