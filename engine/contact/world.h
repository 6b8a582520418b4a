// The world of chapter 5: bodies with shapes, their contacts, joints, and the step that ties
// chapter 2's motion, chapter 3's solver and chapter 4's contacts together.
//
//   World::step, t → t + Δt, in the order of the chapter-5 walk-through:
//     1. forces      F_ext = m g + whatever was applied since the last step       (eq. 5-2)
//     2. collision   broad phase (sort and sweep), then each pair's deepest point  (Fig 4-2)
//     3. cache       cached points re-placed (eq. 5-12), fresh ones merged         (Fig 4-2..4-5)
//     4. rows        contact rows (eq. 4-3, 5-8), each pair's followed by its friction
//                    rows, then the joints' rows; each pair and joint records where its
//                    rows went (the row map); the MLCP assembled once, as they are
//                    written                                                       (eq. 5-11, 5-19)
//     5. solve       J B λ = η by PGS, warm started from the cached λ              (eq. 3-16, 5-21)
//     6. forces Jᵀλ  F_c = Jᵀ λ added to each body                                (eq. 3-11, 5-9)
//     7. integrate   chapter 2's step under F_ext + F_c                          (eq. 2-1..2-8)
//   λ is a force; the impulse over the step is λ Δt. With split impulse (the default, beyond
//   the text) step 5 also solves for the push-out velocity, which step 7 lends to the bodies
//   for the position update only. Where PGS sweeps in parts, step 6 is made in its last sweep,
//   each group's terms once its λ are final (PgsSolver::solve's `forces_to`): the same sums.
// Step k goes from t = k Δt to t = (k + 1) Δt.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "constraints/constrained_step.h"
#include "constraints/constraint.h"
#include "constraints/mlcp.h"
#include "constraints/pgs_solver.h"
#include "constraints/step_settings.h"
#include "contact/contact_cache.h"
#include "contact/contact_rows.h"
#include "contact/split_impulse.h"
#include "contact/step_times.h"
#include "contact/world_report.h"

namespace lamina {

class StepMethod;  // step_method.h: steps 5–7 taken another way (chapter 6)

struct WorldSettings {
  std::string solver = "pgs";           // the method these switches make (solvers.h), for captions
  StepSettings step;                    // g, Δt, β (of contacts and joints), PGS sweeps
  int position_iterations = 3;          // PGS sweeps of the split-impulse position MLCP (Box2D: 3)
  ContactSettings contact;              // slop, restitution, position correction
  CacheSettings cache;                  // the contact cache on or off, and its margins
  // Makes the method that takes steps 5–7 (step_method.h); empty: the World's own PGS step.
  std::function<std::unique_ptr<StepMethod>()> method;
  // Threads that take each step, 1 to 64: collision, the contact cache, the rows, the MLCP's
  // packing and the integration split between them, PGS's sweeps a pipeline (pgs_solver.h). Any
  // number gives the same state bit for bit; only the time differs (more threads than cores:
  // far slower, docs/performance.md).
  int threads = 1;
  // The bodies a World needs before its steps are taken on those threads: a smaller World's
  // pieces of work are too small to pay for handing them over between threads, and its steps
  // are taken on the calling thread, with the same bits (docs/performance.md, *Small worlds on
  // one thread*). 0: every step on the threads.
  int threads_min_bodies = 128;
};

class World {
 public:
  // Throws std::invalid_argument naming the first setting out of range.
  explicit World(const WorldSettings& settings = WorldSettings());
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  // Adds a body with its shape and material and returns its index. Throws
  // std::invalid_argument if the body's state is not finite or leaves the x–y plane (x_z, v_z,
  // ω_x, ω_y ≠ 0 or a tilt out of the plane), or the shape or material is out of range.
  int add_body(const RigidBody& body, const Shape& shape, const Material& material = Material());
  // A dynamic box of the given density (kg/m², mass = density × area), half extents, centre, angle.
  int add_box(double density, double half_x, double half_y, const Vec3& x, double angle = 0.0,
              const Material& material = Material());
  // A static box (the ground, a ramp): it never moves.
  int add_static_box(double half_x, double half_y, const Vec3& x, double angle = 0.0,
                     const Material& material = Material());
  // A dynamic disc of the given density and radius.
  int add_circle(double density, double radius, const Vec3& x,
                 const Material& material = Material());
  // Adds a joint (engine/constraints) and returns its index; its rows follow the contact rows
  // every step. Two bodies joined by a joint do not collide with each other (Box2D's default,
  // collideConnected false). Throws std::invalid_argument for a joint that names a body the
  // world does not have, or that joins static bodies or the world only (it can move nothing,
  // and PGS would divide by d = 0).
  int add_joint(std::unique_ptr<Constraint> joint);
  // Adds force f at world point p to a dynamic body before the next step (eq. 1-31..1-33).
  // Throws std::invalid_argument for a static body, or an f or p that is not finite or leaves
  // the plane.
  void apply_force_at(int body, const Vec3& f, const Vec3& p);

  // Advances the world by Δt. The second form also fills `report` with what was solved.
  void step();
  void step(WorldReport& report);
  // Steps taken by all the Worlds of this process so far: how a test sees that a program
  // simulated its run once (tests/cli/test_cli_simulation.cpp).
  static long steps_in_process();
  // Whether the last step was taken on the threads the settings ask for (more than one, and
  // bodies enough: WorldSettings::threads_min_bodies).
  bool stepped_on_threads() const { return team_ != nullptr; }
  // The wall-clock time of each phase of the steps taken so far (step_times.h).
  const StepTimes& step_times() const { return step_times_; }
  // The same over the steps after the first, which does one-off work (every buffer grows to the
  // scene's size); over the first when it is the only one.
  StepTimes step_times_after_first() const;

  const WorldSettings& settings() const { return settings_; }
  const std::vector<RigidBody>& bodies() const { return bodies_; }
  // The first body (in the order added) whose x, q, v or ω the last step left non-finite: where
  // a run that diverged shows it (`lamina run` stops there). Nothing while every state is finite.
  // Each thread looks at the bodies it integrated, at the end of the step, while they are still
  // in its core's cache.
  std::optional<std::size_t> first_non_finite_body() const { return first_non_finite_body_; }
  const Shape& shape(int index) const { return shapes_.at(index); }
  double time() const { return time_; }  // t, in s
  // The contacts solved in the last step (point, normal, cached or fresh, λ, their rows).
  const std::vector<ContactPair>& contact_pairs() const { return cache_.pairs(); }
  std::vector<ContactInfo> contacts() const { return contact_infos(cache_.pairs()); }
  // The joints, in the order added, and where each one's rows sat in the last step.
  int joint_count() const { return static_cast<int>(joints_.size()); }
  const Constraint& joint(int index) const { return *joints_.at(index).constraint; }
  RowRange joint_rows(int index) const { return joints_.at(index).rows; }

 private:
  struct Joint {
    std::unique_ptr<Constraint> constraint;
    RowRange rows;  // its rows in the last step's MLCP
  };

  void advance(WorldReport* report);
  void apply_forces();
  void detect_collisions();
  // The narrow phase of candidate_pairs_[first, last): their collisions, in order, and the
  // cached pairs it recycled instead, marked in `recycled` (by their index in the cache).
  void find_collisions(std::size_t first, std::size_t last, std::vector<FreshCollision>& found,
                       std::vector<unsigned char>& recycled) const;
  void update_cache();
  void build_rows();
  // Steps 5 and 6.
  void solve(WorldReport* report);
  void take_method_step(WorldReport* report);
  void remember_lambdas(WorldReport* report);
  void find_non_finite_body();

  WorldSettings settings_;
  double time_ = 0.0;                  // t, in s
  std::optional<std::size_t> first_non_finite_body_;  // after the last step
  StepTimes step_times_;               // each phase's time, summed over the steps taken
  StepTimes first_step_times_;         // step_times_ after the first step
  std::vector<RigidBody> bodies_;      // the bodies, in the order they were added
  std::vector<Shape> shapes_;          // bodies_[i]'s shape
  std::vector<Material> materials_;    // bodies_[i]'s friction and restitution
  std::vector<Joint> joints_;          // the joints, their rows after the contacts'
  std::vector<const Constraint*> joint_views_;  // joints_' constraints, for a StepMethod
  std::unique_ptr<StepMethod> method_;  // steps 5–7 when the settings name one (chapter 6)
  std::vector<BodyPair> jointed_;      // pairs of bodies joined by a joint, sorted: never collide
  ContactCache cache_;                 // the contacts kept from step to step
  WarmStart joint_warm_start_;         // the joints' λ from the last step

  // Working data of one step, kept so that steps reuse their memory (a steady step allocates
  // nothing: tests/test_step_allocations.cpp).
  std::vector<Pose2> poses_;                 // each body's planar pose at t
  std::vector<Aabb> boxes_;                  // each body's bounding box at t
  SweepMemory sweep_memory_;                 // bodies by min.x, kept for the next sort
  std::vector<BodyPair> candidate_pairs_;    // the broad phase's pairs
  std::vector<FreshCollision> fresh_;        // the narrow phase's deepest points
  PerRun<std::vector<FreshCollision>> fresh_of_thread_;  // on threads: each run's
  std::vector<unsigned char> recycled_;  // per cached pair: recycled by the narrow phase
  std::vector<ConstraintRow> rows_;          // the joints' rows as written (the contacts' are
                                             // packed into velocity_ as they are written)
  std::size_t first_joint_row_ = 0;          // where the joints' rows start in the MLCP
  std::vector<Vec6> unconstrained_;          // V/Δt + M⁻¹ F_ext per body (eq. 3-16), m/s², rad/s²
  Mlcp velocity_;                            // the velocity MLCP (eq. 3-16), assembled once
  std::vector<double> lambda_;               // its λ, in N: the warm start λ_exp, then solved
  SplitImpulse split_impulse_;               // the position MLCP and each body's push-out
  std::unique_ptr<Workers> workers_;         // the threads past the first, when settings ask
  Workers* team_ = nullptr;                  // this step's threads: workers_ in a World of
                                             // bodies enough (threads_min_bodies), else none
  PgsSolver pgs_;                            // the sweeps' a = B λ, for both MLCPs in turn
  std::vector<RowRange> joint_rows_;         // each joint's rows, for a StepMethod
};

// E = Σ (½ m vᵀv + ½ ωᵀ I ω) − m g·x over the moving bodies, in J: eq. 1-47 plus gravity's
// potential energy, 0 at x = 0 (the text's E is kinetic only).
double mechanical_energy(const World& world);

}  // namespace lamina
