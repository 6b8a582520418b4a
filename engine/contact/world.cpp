#include "contact/world.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <string>
#include <utility>

#include "constraints/jacobian_rows.h"
#include "contact/step_method.h"
#include "kinematics/momentum.h"
#include "kinematics/require.h"
#include "motion/integrator.h"

namespace lamina {
namespace {

std::atomic<long> steps_taken_in_process{0};  // World::steps_in_process()

// A body in the x–y plane: centre at z = 0, turned about z only, moving in the plane.
bool is_planar(const RigidBody& b) {
  return b.x.z() == 0.0 && b.q.x() == 0.0 && b.q.y() == 0.0 && b.v.z() == 0.0 &&
         b.angular_velocity.x() == 0.0 && b.angular_velocity.y() == 0.0;
}

void validate(const WorldSettings& s) {
  validate(s.step);
  require(s.threads >= 1 && s.threads <= max_threads,
          "world: threads must be 1 to " + std::to_string(max_threads) + ", got " +
              std::to_string(s.threads));
  require(s.threads_min_bodies >= 0,
          "world: threads_min_bodies must be ≥ 0, got " + std::to_string(s.threads_min_bodies));
  require(s.position_iterations >= 1,
          "world: position_iterations must be ≥ 1, got " + std::to_string(s.position_iterations));
  validate(s.contact);
  validate(s.cache);
}

}  // namespace

World::World(const WorldSettings& settings) : settings_(settings) {
  validate(settings_);
  // The pitfall baumgarte-no-slop: Baumgarte's bias with no slop, whatever the method asked
  if (settings_.step.pitfalls.has(Pitfall::baumgarte_no_slop)) {
    settings_.contact.correction = PositionCorrection::baumgarte;
    settings_.contact.slop = 0.0;
  }
  if (settings_.method) method_ = settings_.method();
  if (settings_.threads > 1) workers_ = std::make_unique<Workers>(settings_.threads);
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

int World::add_body(const RigidBody& body, const Shape& shape, const Material& material) {
  const std::string name = "body " + std::to_string(bodies_.size());
  require(body.has_finite_state(),
          name + " has a position, orientation or velocity that is not finite");
  require(is_planar(body),
          name + " leaves the x–y plane (x_z, v_z, ω_x, ω_y and the tilt must be 0)");
  validate(shape);
  validate(material);
  bodies_.push_back(body);
  shapes_.push_back(shape);
  materials_.push_back(material);
  return static_cast<int>(bodies_.size()) - 1;
}

int World::add_box(double density, double half_x, double half_y, const Vec3& x, double angle,
                   const Material& material) {
  return add_body(box_body(density, half_x, half_y, x, angle), Shape::box(half_x, half_y),
                  material);
}

int World::add_static_box(double half_x, double half_y, const Vec3& x, double angle,
                          const Material& material) {
  return add_body(RigidBody::static_body(x, planar_orientation(angle)), Shape::box(half_x, half_y),
                  material);
}

int World::add_circle(double density, double radius, const Vec3& x, const Material& material) {
  return add_body(disc_body(density, radius, x), Shape::circle(radius), material);
}

int World::add_joint(std::unique_ptr<Constraint> joint) {
  const std::string name = "joint " + std::to_string(joints_.size());
  const std::array<int, 2> ends = joint->bodies();
  const int count = static_cast<int>(bodies_.size());
  require(ends[0] < count && ends[1] < count,
          name + " names a body the world does not have (it has " + std::to_string(count) + ")");
  // A joint's rows on static bodies alone move nothing: d = J M⁻¹ Jᵀ = 0 (jacobian_rows.h)
  require(holds_block(bodies_, ends[0]) || holds_block(bodies_, ends[1]),
          name + " joins only static bodies (or the world): it can move nothing");
  if (ends[0] >= 0 && ends[1] >= 0) {
    const BodyPair pair{std::min(ends[0], ends[1]), std::max(ends[0], ends[1])};
    const auto at = std::lower_bound(jointed_.begin(), jointed_.end(), pair);
    if (at == jointed_.end() || !(*at == pair)) jointed_.insert(at, pair);
  }
  joint_views_.push_back(joint.get());
  joints_.push_back({std::move(joint), RowRange{}});
  return static_cast<int>(joints_.size()) - 1;
}

void World::apply_force_at(int body, const Vec3& f, const Vec3& p) {
  require(body >= 0 && body < static_cast<int>(bodies_.size()) && !bodies_[body].is_static(),
          "world: a force needs a dynamic body, got body " + std::to_string(body));
  require(f.allFinite() && p.allFinite() && f.z() == 0.0 && p.z() == 0.0,
          "world: a force and its point must be finite and in the x–y plane");
  bodies_[body].apply_force_at(f, p);
}

long World::steps_in_process() { return steps_taken_in_process.load(std::memory_order_relaxed); }

void World::step() { advance(nullptr); }

void World::step(WorldReport& report) { advance(&report); }

StepTimes World::step_times_after_first() const {
  return step_times_.steps > 1 ? step_times_.since(first_step_times_) : step_times_;
}

void World::advance(WorldReport* report) {
  // On the threads once the World has bodies enough: the same bits either way
  const bool big_enough =
      bodies_.size() >= static_cast<std::size_t>(settings_.threads_min_bodies);
  team_ = big_enough ? workers_.get() : nullptr;
  pgs_.use_workers(team_);
  const Workers::Awake awake(team_);  // the threads wait spinning between the phases
  if (report != nullptr) {
    *report = WorldReport();  // a reused report keeps nothing of its last step
    report->time = time_;
    report->bodies = bodies_;
  }
  PhaseClock clock(step_times_);
  apply_forces();          // 1
  clock.lap(StepPhase::forces);
  detect_collisions();     // 2
  clock.lap(StepPhase::collision);
  update_cache();          // 3
  clock.lap(StepPhase::cache);
  build_rows();            // 4
  clock.lap(StepPhase::rows);
  if (method_) {
    take_method_step(report);  // 5–7, chapter 6's way
    clock.lap(StepPhase::solve);
  } else {
    solve(report);             // 5, and 6. eq. 3-11, 5-9: F_c = Jᵀ λ
    clock.lap(StepPhase::solve);
    // 7. eq. 2-1..2-8 under F_ext + F_c, with split impulse's push-out
    integrate_with_push_out(bodies_, split_impulse_.push_out(), settings_.step.dt,
                            settings_.step.pitfalls, team_);
    clock.lap(StepPhase::integrate);
  }
  find_non_finite_body();
  clock.lap(StepPhase::checks);
  if (++step_times_.steps == 1) first_step_times_ = step_times_;
  time_ += settings_.step.dt;
  steps_taken_in_process.fetch_add(1, std::memory_order_relaxed);
}

void World::apply_forces() {
  // eq. 5-2: F_ext = m g on the dynamic bodies, on top of forces applied since the last step;
  // each run its share of the bodies, the share it integrates
  const int runs = runs_on(team_);
  run_on(team_, [&](int t) {
    const auto [first, last] = share_of(bodies_.size(), t, runs);
    for (std::size_t i = first; i < last; ++i) apply_gravity(bodies_[i], settings_.step.gravity);
  });
}

void World::detect_collisions() {
  poses_.resize(bodies_.size());
  boxes_.resize(bodies_.size());
  const int runs = runs_on(team_);
  run_on(team_, [&](int t) {  // each run its share of the bodies
    const auto [first, last] = share_of(bodies_.size(), t, runs);
    for (std::size_t i = first; i < last; ++i) {
      poses_[i] = planar_pose(bodies_[i]);
      boxes_[i] = bounding_box(shapes_[i], poses_[i]);
    }
  });
  sort_and_sweep(boxes_, sweep_memory_, candidate_pairs_, team_);
  // each run its share of the candidates, in order, its collisions appended in order
  fresh_of_thread_.resize(runs);
  // a flag per cached pair, set by the run that meets it among its candidates (one at most:
  // both are sorted by pair)
  recycled_.assign(cache_.pairs().size(), 0);
  run_on(team_, [&](int t) {
    const auto [first, last] = share_of(candidate_pairs_.size(), t, runs);
    find_collisions(first, last, runs == 1 ? fresh_ : fresh_of_thread_[t], recycled_);
  });
  if (runs > 1) join_runs(fresh_of_thread_, fresh_, team_);
}

void World::find_collisions(std::size_t first, std::size_t last,
                            std::vector<FreshCollision>& found,
                            std::vector<unsigned char>& recycled) const {
  found.clear();
  // the cache's pairs, walked along with the sorted candidates from this run's first (a run
  // that starts mid-way once walked every pair before it: on two threads, the second thread
  // read half the cache's pairs, one cache line each, before its first candidate)
  size_t cursor = first < last ? cache_.cursor_at(candidate_pairs_[first]) : 0;
  for (std::size_t i = first; i < last; ++i) {
    const BodyPair& pair = candidate_pairs_[i];
    if (bodies_[pair.first].is_static() && bodies_[pair.second].is_static()) continue;
    if (std::binary_search(jointed_.begin(), jointed_.end(), pair)) continue;
    // With the cache off there is nothing to break ties against: a first contact every step.
    const ContactPair* kept = settings_.cache.enabled ? cache_.find(pair, cursor) : nullptr;
    // contact recycling: a full pair that barely moved keeps its points, not collided again
    if (kept != nullptr && recyclable(*kept, poses_, settings_.cache)) {
      recycled[cursor] = 1;
      continue;
    }
    const CachedPoints cached = kept != nullptr ? cached_points(*kept, poses_) : CachedPoints{};
    const std::optional<Collision> collision =
        collide(shapes_[pair.first], poses_[pair.first], shapes_[pair.second],
                poses_[pair.second], cached, settings_.cache.ties);
    if (collision) found.push_back({pair, *collision});
  }
}

void World::update_cache() {
  cache_.update(fresh_, recycled_, poses_, shapes_, materials_, settings_.cache, team_);
}

void World::build_rows() {
  // the joints' rows, numbered from 0 until they follow the contacts' in the MLCP
  rows_.clear();
  for (Joint& joint : joints_) {
    joint.rows.first = static_cast<int>(rows_.size());
    joint.constraint->write_rows(bodies_, settings_.step.dt, settings_.step.beta, rows_);
    joint.rows.count = static_cast<int>(rows_.size()) - joint.rows.first;
  }
  // eq. 3-16: J B λ = η with B = M⁻¹ Jᵀ, η = ζ/Δt − J (V/Δt + M⁻¹ F_ext), assembled as the
  // contacts' rows are written (λ_exp = the cached λ, zero with the cache off), then the joints'
  const double dt = settings_.step.dt;
  unconstrained_velocities(bodies_, dt, unconstrained_, team_);
  ContactRows contact_rows = cache_.rows(bodies_, settings_.contact, settings_.step, lambda_);
  velocity_.assemble(bodies_, contact_rows, rows_, unconstrained_, dt, team_);
  first_joint_row_ = static_cast<std::size_t>(velocity_.row_count()) - rows_.size();
  for (Joint& joint : joints_) joint.rows.first += static_cast<int>(first_joint_row_);
  // the joints' rows, λ_exp = last step's λ
  joint_warm_start_.append_guess(rows_.data(), rows_.data() + rows_.size(), lambda_);
  // the pitfall no-warm-start: every λ_exp = 0, the cache's points kept
  if (settings_.step.pitfalls.has(Pitfall::no_warm_start)) {
    std::fill(lambda_.begin(), lambda_.end(), 0.0);
  }
}

void World::solve(WorldReport* report) {
  // Split impulse's position MLCP first: its ζ does not depend on the velocity λ, so that
  // without a report both are solved side by side (PgsSolver::solve_both)
  const bool push = split_impulse_.prepare(velocity_, cache_.pairs(), settings_.contact,
                                           settings_.step, report != nullptr, team_);
  const Pitfalls pitfalls = settings_.step.pitfalls;
  // eq. 3-24 by Projected Gauss-Seidel, friction bounds ±μ λc read as λc changes
  if (push && report == nullptr) {
    SweepResult velocity_sweeps;
    SweepResult position_sweeps;
    pgs_.solve_both(velocity_, lambda_.data(), {settings_.step.iterations, 0.0, false},
                    velocity_sweeps, split_impulse_.position(), split_impulse_.lambda().data(),
                    {settings_.position_iterations, 0.0, false}, position_sweeps, pitfalls,
                    &bodies_);
  } else {
    solve_recording(pgs_, velocity_, settings_.step.iterations, lambda_,
                    report != nullptr ? &report->velocity : nullptr, pitfalls, &bodies_);
    if (push) {
      solve_recording(pgs_, split_impulse_.position(), settings_.position_iterations,
                      split_impulse_.lambda(), report != nullptr ? &report->position : nullptr,
                      pitfalls);
    }
  }
  remember_lambdas(report);
  if (push) split_impulse_.take_push_out(pgs_, settings_.step.dt, team_);
}

void World::take_method_step(WorldReport* report) {
  joint_rows_.clear();
  for (const Joint& joint : joints_) joint_rows_.push_back(joint.rows);
  if (report != nullptr) {
    report->velocity.mlcp = velocity_;
    report->velocity.lambda_exp = Eigen::Map<const Eigen::VectorXd>(
        lambda_.data(), static_cast<Eigen::Index>(lambda_.size()));
  }
  const StepProblem problem{settings_,   first_joint_row_, cache_.pairs(), joint_views_,
                            joint_rows_, velocity_,        team_};
  method_->take_step(problem, bodies_, lambda_, report);
  if (report != nullptr) {
    report->velocity.solution.lambda = Eigen::Map<const Eigen::VectorXd>(
        lambda_.data(), static_cast<Eigen::Index>(lambda_.size()));
    SweepResult& solution = report->velocity.solution;
    solution.iterations = static_cast<int>(solution.residuals.size());
    // a method that records only its answer (one residual) has that answer as its one pass
    if (solution.lambdas.size() < solution.residuals.size()) {
      solution.lambdas.assign(1, solution.lambda);
    }
  }
  remember_lambdas(report);
}

void World::remember_lambdas(WorldReport* report) {
  cache_.store_lambdas(lambda_.data(), team_);
  joint_warm_start_.remember(rows_.data(), rows_.data() + rows_.size(),
                             lambda_.data() + first_joint_row_);
  if (report != nullptr) {
    report->pairs = cache_.pairs();
    for (const Joint& joint : joints_) report->joints.push_back(joint.rows);
  }
}

void World::find_non_finite_body() {
  // each run its share of the bodies, the share it integrated; then the first of the runs' firsts
  const int runs = runs_on(team_);
  std::array<std::size_t, max_runs> first_of_run{};  // per run; bodies_.size(): none
  run_on(team_, [&](int t) {
    const auto [first, last] = share_of(bodies_.size(), t, runs);
    std::size_t i = first;
    while (i < last && bodies_[i].has_finite_state()) ++i;
    first_of_run[static_cast<std::size_t>(t)] = i < last ? i : bodies_.size();
  });
  const std::size_t first = *std::min_element(first_of_run.begin(), first_of_run.begin() + runs);
  first_non_finite_body_ =
      first < bodies_.size() ? std::optional<std::size_t>(first) : std::nullopt;
}

double mechanical_energy(const World& world) {
  const Vec3& g = world.settings().step.gravity;
  double energy = 0.0;
  for (const RigidBody& b : world.bodies()) {
    if (b.is_static()) continue;
    // eq. 1-47 and m g h
    energy +=
        kinetic_energy(b.mass, b.v, b.inertia_world(), b.angular_velocity) - b.mass * g.dot(b.x);
  }
  return energy;
}

}  // namespace lamina
