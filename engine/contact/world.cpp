#include "contact/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "constraints/mlcp.h"
#include "motion/integrator.h"

namespace lamina {
namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("world: " + message);
}

void require_at_least(double value, double low, const char* name) {
  require(std::isfinite(value) && value >= low,
          std::string(name) + " must be finite and ≥ " + std::to_string(low) + ", got " +
              std::to_string(value));
}

void validate(const WorldSettings& s) {
  require(s.gravity.allFinite() && s.gravity.z() == 0.0, "gravity must be finite and in the plane");
  require(std::isfinite(s.dt) && s.dt > 0.0, "dt must be finite and > 0, got " + std::to_string(s.dt));
  // 0 sweeps is allowed: λ stays at its warm start (scene_limits.h)
  require(s.iterations >= 0, "iterations must be ≥ 0, got " + std::to_string(s.iterations));
  require(s.position_iterations >= 1,
          "position_iterations must be ≥ 1, got " + std::to_string(s.position_iterations));
  require(std::isfinite(s.contact.beta) && s.contact.beta >= 0.0 && s.contact.beta <= 1.0,
          "contact.beta must be in [0, 1], got " + std::to_string(s.contact.beta));
  require_at_least(s.contact.slop, 0.0, "contact.slop");
  require_at_least(s.contact.restitution_threshold, 0.0, "contact.restitution_threshold");
  require_at_least(s.cache.keep_margin, 0.0, "cache.keep_margin");
  require_at_least(s.cache.merge_distance, 0.0, "cache.merge_distance");
  require_at_least(s.cache.drift_limit, 0.0, "cache.drift_limit");
  require_at_least(s.cache.tie_tolerance, 0.0, "cache.tie_tolerance");
}

// A body in the x–y plane: centre at z = 0, turned about z only, moving in the plane.
bool is_planar(const RigidBody& b) {
  return b.x.z() == 0.0 && b.q.x() == 0.0 && b.q.y() == 0.0 && b.v.z() == 0.0 &&
         b.angular_velocity.x() == 0.0 && b.angular_velocity.y() == 0.0;
}

// Whether a row acts on a body that moves. A row on static bodies (or the world) alone has
// d = J M⁻¹ Jᵀ = 0, and PGS divides by d (eq. 3-24's sweep).
bool moves_a_body(const ConstraintRow& row, const std::vector<RigidBody>& bodies) {
  return std::any_of(row.Jmap.begin(), row.Jmap.end(),
                     [&](int b) { return b >= 0 && !bodies[b].is_static(); });
}

// λ kept in a std::vector, seen as an Eigen vector without a copy.
Eigen::Map<const Eigen::VectorXd> lambda_view(const std::vector<double>& lambda) {
  return {lambda.data(), static_cast<Eigen::Index>(lambda.size())};
}

// PGS on λ in place, λ_exp on entry. With a report, whose mlcp holds the rows assembled, it also
// records λ_exp, the residual after every sweep, λ and W = J B λ − η (eq. 3-23).
void solve_in_place(PgsWorkspace& solver, int iterations, std::vector<double>& lambda,
                    StepReport* report) {
  PgsSettings settings;
  settings.iterations = iterations;
  settings.record_residuals = report != nullptr;
  PgsResult sweeps;  // the sweeps run and their residuals; λ itself stays in `lambda`
  if (report != nullptr) report->lambda_exp = lambda_view(lambda);
  solver.solve(lambda.data(), settings, report != nullptr ? &report->mlcp : nullptr, sweeps);
  if (report == nullptr) return;
  sweeps.lambda = lambda_view(lambda);
  report->W = complementarity_slack(report->mlcp, lambda_view(lambda));
  report->solution = std::move(sweeps);
}

// No point deeper than the slop and no gap to close: every η ≤ 0, so λ = 0 solves the position
// MLCP (W = −η ≥ 0, eq. 3-24) and PGS started from λ = 0 keeps it: no push-out this step.
// Box2D's position pass stops early in the same case.
bool nothing_to_push(const std::vector<double>& eta) {
  return std::all_of(eta.begin(), eta.end(), [](double e) { return e <= 0.0; });
}

}  // namespace

World::World(const WorldSettings& settings) : settings_(settings) { validate(settings_); }

int World::add_body(const RigidBody& body, const Shape& shape, const Material& material) {
  const std::string name = "body " + std::to_string(bodies_.size());
  require(body.has_finite_state(),
          name + " has a position, orientation or velocity that is not finite");
  require(is_planar(body),
          name + " leaves the x–y plane (x_z, v_z, ω_x, ω_y and the tilt must be 0)");
  // The factories check the sizes; a hand-made Shape is checked the same way.
  const Shape checked = shape.is_box() ? Shape::box(shape.half_extents.x(), shape.half_extents.y())
                                       : Shape::circle(shape.radius);
  validate(material);
  bodies_.push_back(body);
  shapes_.push_back(checked);
  materials_.push_back(material);
  return static_cast<int>(bodies_.size()) - 1;
}

int World::add_box(double density, double half_x, double half_y, const Vec3& x, double angle,
                   const Material& material) {
  return add_body(box_body(density, half_x, half_y, x, angle), Shape::box(half_x, half_y), material);
}

int World::add_static_box(double half_x, double half_y, const Vec3& x, double angle,
                          const Material& material) {
  return add_body(RigidBody::static_body(x, planar_orientation(angle)), Shape::box(half_x, half_y),
                  material);
}

int World::add_circle(double density, double radius, const Vec3& x, const Material& material) {
  return add_body(disc_body(density, radius, x), Shape::circle(radius), material);
}

void World::add_joint(std::unique_ptr<Constraint> joint) {
  std::vector<ConstraintRow> rows;
  joint->write_rows(bodies_, settings_.dt, settings_.contact.beta, rows);
  require(std::all_of(rows.begin(), rows.end(),
                      [&](const ConstraintRow& row) { return moves_a_body(row, bodies_); }),
          "joint " + std::to_string(joints_.size()) +
              " joins only static bodies: it can move nothing");
  for (const ConstraintRow& row : rows) {
    if (row.is_one_body()) continue;
    const BodyPair pair{std::min(row.Jmap[0], row.Jmap[1]), std::max(row.Jmap[0], row.Jmap[1])};
    const auto at = std::lower_bound(jointed_.begin(), jointed_.end(), pair);
    if (at == jointed_.end() || !(*at == pair)) jointed_.insert(at, pair);
  }
  joints_.push_back(std::move(joint));
}

void World::step() { advance(nullptr); }

void World::step(WorldReport& report) { advance(&report); }

void World::advance(WorldReport* report) {
  if (report != nullptr) {
    *report = WorldReport();  // a reused report keeps nothing of its last step
    report->time = time_;
  }
  apply_forces();          // 1
  detect_collisions();     // 2
  update_cache();          // 3
  build_rows();            // 4
  solve(report);           // 5
  add_constraint_forces(); // 6
  integrate_bodies();      // 7
  time_ += settings_.dt;
}

void World::apply_forces() {
  // eq. 5-2: F_ext = m g (a static body has m = 0), on top of forces applied since the last step
  apply_gravity(bodies_, settings_.gravity);
}

void World::detect_collisions() {
  poses_.resize(bodies_.size());
  boxes_.resize(bodies_.size());
  for (size_t i = 0; i < bodies_.size(); ++i) {
    poses_[i] = planar_pose(bodies_[i]);
    boxes_[i] = bounding_box(shapes_[i], poses_[i]);
  }
  sort_and_sweep(boxes_, sweep_order_, candidate_pairs_);
  fresh_.clear();
  size_t cursor = 0;  // the cache's pairs, walked along with the sorted candidates
  for (const BodyPair& pair : candidate_pairs_) {
    if (bodies_[pair.first].is_static() && bodies_[pair.second].is_static()) continue;
    if (std::binary_search(jointed_.begin(), jointed_.end(), pair)) continue;
    // With the cache off there is nothing to break ties against: a first contact every step.
    const CachedPoints cached =
        settings_.cache.enabled ? cache_.cached_points(pair, poses_, cursor) : CachedPoints{};
    const std::optional<Collision> collision =
        collide(shapes_[pair.first], poses_[pair.first], shapes_[pair.second],
                poses_[pair.second], cached, settings_.cache.tie_tolerance);
    if (collision) fresh_.push_back({pair, *collision});
  }
}

void World::update_cache() { cache_.update(fresh_, poses_, shapes_, materials_, settings_.cache); }

void World::build_rows() {
  rows_.clear();
  warm_start_.clear();
  kinds_.clear();
  add_contact_rows(cache_.pairs(), bodies_, settings_.contact, settings_.dt, rows_, warm_start_,
                   kinds_);
  joint_rows_.clear();
  for (const auto& joint : joints_) {
    joint->write_rows(bodies_, settings_.dt, settings_.contact.beta, joint_rows_);
  }
  joint_warm_start_.append_guess(joint_rows_, warm_start_);
  rows_.insert(rows_.end(), joint_rows_.begin(), joint_rows_.end());
  kinds_.insert(kinds_.end(), joint_rows_.size(), RowKind::joint);
}

void World::solve(WorldReport* report) {
  const double dt = settings_.dt;
  // eq. 3-16: J B λ = η with B = M⁻¹ Jᵀ, η = ζ/Δt − J (V/Δt + M⁻¹ F_ext)
  unconstrained_velocities(bodies_, dt, unconstrained_);
  velocity_solver_.assemble(bodies_, rows_, unconstrained_, dt);
  if (report != nullptr) report->velocity.mlcp = assemble_mlcp(bodies_, rows_, unconstrained_, dt);
  // λ_exp: the cached λ of every contact (zero with the cache off), last step's for joints
  lambda_ = warm_start_;
  // eq. 3-24 by Projected Gauss-Seidel, friction bounds ±μ λc read as λc changes
  solve_in_place(velocity_solver_, settings_.iterations, lambda_,
                 report != nullptr ? &report->velocity : nullptr);
  store_contact_lambdas(cache_.pairs(), lambda_, settings_.contact);
  const auto joint_count = static_cast<Eigen::Index>(joint_rows_.size());
  joint_warm_start_.remember(joint_rows_, lambda_view(lambda_).tail(joint_count));
  if (report != nullptr) {
    report->contacts = contact_infos(cache_.pairs());
    report->kinds = kinds_;
  }
  solve_positions(report);
}

void World::solve_positions(WorldReport* report) {
  push_out_.clear();
  if (settings_.contact.correction != PositionCorrection::split_impulse) return;
  const double dt = settings_.dt;
  // The velocity MLCP's contact rows again, each asking J V_p ≥ its push-out (or gap) ζ
  position_targets(cache_.pairs(), settings_.contact, dt, position_rows_, position_eta_);
  // eq. 3-16 for the push-out alone: the bodies start from rest under no force, so η = ζ/Δt
  for (double& eta : position_eta_) eta /= dt;
  if (report == nullptr && nothing_to_push(position_eta_)) return;  // a report shows the sweeps
  position_solver_.copy_rows(velocity_solver_, position_rows_, position_eta_);
  if (report != nullptr) report->position.mlcp = position_mlcp();
  position_lambda_.assign(position_rows_.size(), 0.0);
  solve_in_place(position_solver_, settings_.position_iterations, position_lambda_,
                 report != nullptr ? &report->position : nullptr);
  // The push-out velocity of each body: M⁻¹ Jᵀ λ Δt = B λ Δt
  push_out_.resize(bodies_.size());
  for (size_t b = 0; b < bodies_.size(); ++b) {
    push_out_[b] = position_solver_.velocity_change(static_cast<int>(b)) * dt;
  }
}

Mlcp World::position_mlcp() const {
  std::vector<ConstraintRow> rows;
  add_position_rows(cache_.pairs(), rows_, settings_.contact, settings_.dt, rows);
  const std::vector<Vec6> at_rest(bodies_.size(), Vec6::Zero());
  return assemble_mlcp(bodies_, std::move(rows), at_rest, settings_.dt);
}

void World::add_constraint_forces() {
  // eq. 3-11, 5-9: F_c = Jᵀ λ
  velocity_solver_.add_constraint_forces(bodies_, lambda_.data());
}

void World::integrate_bodies() {
  for (size_t i = 0; i < bodies_.size(); ++i) {
    RigidBody& body = bodies_[i];
    if (body.is_static()) {
      body.clear_forces();
      continue;
    }
    // Split impulse: the push-out velocity moves the body in this step and is then taken back.
    const Vec6 push = push_out_.empty() ? Vec6::Zero() : push_out_[i];
    body.v += push.head<3>();
    body.angular_velocity += push.tail<3>();
    // eq. 2-1..2-8 under F_ext + F_c
    integrate(body, settings_.dt);
    body.v -= push.head<3>();
    body.angular_velocity -= push.tail<3>();
    body.clear_forces();
  }
}

std::optional<std::size_t> first_non_finite_body(const World& world) {
  const std::vector<RigidBody>& bodies = world.bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies[i].has_finite_state()) return i;
  }
  return std::nullopt;
}

}  // namespace lamina
