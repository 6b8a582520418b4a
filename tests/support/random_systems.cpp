#include "support/random_systems.h"

namespace lamina {
namespace {

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Vec3 random_vec3(std::mt19937& rng, double scale) { return random_matrix(rng, 3, 1, scale); }

// v_z, ω_x and ω_y of a 6-vector [v ω] set to zero: what a planar row keeps.
Vec6 in_plane_part(Vec6 v) {
  v[2] = v[3] = v[4] = 0.0;
  return v;
}

ConstraintRow random_row(std::mt19937& rng, int body_count, Layout layout) {
  ConstraintRow row;
  std::uniform_int_distribution<int> pick(0, body_count - 1);
  row.Jmap[0] = pick(rng);
  if (uniform(rng, 0.0, 3.0) > 1.0) {
    do row.Jmap[1] = pick(rng); while (row.Jmap[1] == row.Jmap[0]);
  }
  for (int k = 0; k < 2; ++k) {
    if (row.Jmap[k] < 0) continue;
    row.Jsp[k] = random_vec6(rng);
    if (layout == Layout::planar) row.Jsp[k] = in_plane_part(row.Jsp[k]);
  }
  row.zeta = uniform(rng, -1.0, 1.0);
  return row;
}

void set_random_bounds(std::mt19937& rng, ConstraintRow& row) {
  const double kind = uniform(rng, 0.0, 3.0);
  if (kind < 1.0) return;
  if (kind < 2.0) {
    row.lambda_min = 0.0;
    return;
  }
  row.lambda_min = uniform(rng, -60.0, 30.0);
  row.lambda_max = row.lambda_min + uniform(rng, 1.0, 60.0);
}

}  // namespace

Eigen::MatrixXd random_matrix(std::mt19937& rng, Eigen::Index rows, Eigen::Index cols, double scale) {
  return Eigen::MatrixXd::NullaryExpr(rows, cols, [&] { return uniform(rng, -scale, scale); });
}

Vec6 random_vec6(std::mt19937& rng) { return random_matrix(rng, 6, 1, 1.0); }

RigidBody random_body(std::mt19937& rng, Layout layout) {
  const Vec3 principal(uniform(rng, 0.5, 2.0), uniform(rng, 0.5, 2.0), uniform(rng, 0.5, 2.0));
  Quat q = Quat(uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0),
                uniform(rng, -1.0, 1.0))
               .normalized();
  // planar: the turn about z alone, so that I⁻¹ turns z into z (block_layout.h)
  if (layout == Layout::planar) q = Quat(q.w(), 0.0, 0.0, q.z()).normalized();
  const Mat3 R = q.toRotationMatrix();
  RigidBody body = RigidBody::dynamic_body(uniform(rng, 1.0, 5.0),
                                           R * principal.asDiagonal() * R.transpose(),
                                           random_vec3(rng, 1.0), q);
  body.v = random_vec3(rng, 1.0);
  body.angular_velocity = random_vec3(rng, 1.0);
  body.force = random_vec3(rng, 10.0);
  body.torque = random_vec3(rng, 1.0);
  return body;
}

RandomSystem random_system(std::mt19937& rng, int body_count, int row_count, bool bounded,
                           Layout layout) {
  RandomSystem sys;
  for (int b = 0; b < body_count; ++b) sys.bodies.push_back(random_body(rng, layout));
  for (int i = 0; i < row_count; ++i) {
    sys.rows.push_back(random_row(rng, body_count, layout));
    if (bounded) set_random_bounds(rng, sys.rows.back());
  }
  sys.dense = build_dense_system(sys.bodies, sys.rows, random_system_dt);
  sys.mlcp = assemble_mlcp(sys.bodies, sys.rows, random_system_dt);
  return sys;
}

RandomSystem random_mlcp_with_friction(std::mt19937& rng, int body_count, int row_count,
                                       Layout layout) {
  RandomSystem sys = random_system(rng, body_count, row_count, false, layout);
  std::uniform_real_distribution<double> kind_of(0.0, 3.0), mu(0.2, 1.0);
  std::vector<int> contact_rows;
  for (int i = 0; i < row_count; ++i) {
    ConstraintRow& row = sys.rows[static_cast<std::size_t>(i)];
    const double kind = kind_of(rng);
    if (kind < 1.0) continue;  // equality
    if (kind < 2.0 || contact_rows.empty()) {
      row.lambda_min = 0.0;  // contact
      contact_rows.push_back(i);
      continue;
    }
    std::uniform_int_distribution<std::size_t> pick(0, contact_rows.size() - 1);
    row.friction_of = contact_rows[pick(rng)];
    row.mu = mu(rng);
  }
  sys.mlcp = assemble_mlcp(sys.bodies, sys.rows, random_system_dt);
  sys.dense = build_dense_system(sys.bodies, sys.rows, random_system_dt);
  return sys;
}

}  // namespace lamina
