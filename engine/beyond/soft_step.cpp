#include "beyond/soft_step.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "motion/integrator.h"

namespace lamina {
namespace {

// A spring of frequency f (Hz) and damping ratio ζ over a substep h, as Box2D v3's b2MakeSoft.
struct Softness {
  double bias_rate = 0.0;      // b, in 1/s
  double mass_scale = 1.0;     // s_m
  double impulse_scale = 0.0;  // s_i
};

Softness soft(double hertz, double zeta, double h) {
  const double omega = 2.0 * M_PI * hertz;
  const double a1 = 2.0 * zeta + h * omega;
  const double a2 = h * omega * a1;
  const double a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

constexpr double contact_hertz = 30.0, contact_damping = 10.0;  // Box2D v3's world defaults
constexpr double joint_hertz = 60.0, joint_damping = 2.0;       // B2_JOINT_CONSTRAINT_*
constexpr double push_out_speed = 3.0;                          // maxContactPushSpeed, m/s

// Box2D v3's constraint graph: 12 colours, the last one the overflow.
constexpr int graph_colours = 11;            // colours 0..10; no two rows of one share a moving body
constexpr int overflow = graph_colours;      // what finds no colour, swept before the colours

enum class Kind { contact, friction, joint, joint_limit };

// One row as the soft step sweeps it.
struct SoftRow {
  Kind kind = Kind::contact;
  std::array<int, 2> bodies{-1, -1};
  std::array<Vec6, 2> J, B;  // J_i's and B_i's blocks
  std::array<Vec2, 2> lever{Vec2::Zero(), Vec2::Zero()};  // a contact's r_k = c − x_k at t, in m
  double mass = 0.0;         // 1/d_i
  double separation = 0.0;   // C at t, in m (contacts, joints)
  Softness softness;
  double max_push = push_out_speed;  // a contact's largest push-out velocity, in m/s
  int friction_of = -1, friction_count = 0;  // a friction row's contact rows
  double mu = 0.0;
  double restitution = 0.0;  // e of a contact row's pair
  double approach = 0.0;     // J V at t, in m/s (restitution)
  double impulse = 0.0;      // P, in N·s
  double total = 0.0;        // Σ P over the step's sweeps (restitution asks whether it pushed)
};

double dot_row(const SoftRow& r, const std::vector<Vec6>& x) {
  double sum = r.J[0].dot(x[static_cast<std::size_t>(r.bodies[0])]);
  if (r.bodies[1] >= 0) sum += r.J[1].dot(x[static_cast<std::size_t>(r.bodies[1])]);
  return sum;
}

void apply(const SoftRow& r, double impulse, std::vector<Vec6>& velocity) {
  velocity[static_cast<std::size_t>(r.bodies[0])] += impulse * r.B[0];
  if (r.bodies[1] >= 0) velocity[static_cast<std::size_t>(r.bodies[1])] += impulse * r.B[1];
}

class SoftStep final : public StepMethod {
 public:
  void take_step(const StepProblem& problem, std::vector<RigidBody>& bodies,
                 std::vector<double>& lambda, WorldReport* report) override {
    const WorldSettings& s = problem.settings;
    const double dt = s.step.dt, h = dt / soft_substeps;
    const Softness contact = soft(std::min(contact_hertz, 0.125 / h), contact_damping, h);
    const Softness against_static = soft(2.0 * std::min(contact_hertz, 0.125 / h), contact_damping, h);
    const Softness joint = soft(std::min(joint_hertz, 0.25 / h), joint_damping, h);
    colour(problem, bodies);
    prepare(problem, bodies, lambda, h, contact, against_static, joint);

    const std::size_t n = bodies.size();
    external_.resize(n);
    start_.resize(n);
    moved_.assign(n, Vec6::Zero());
    turned_.assign(n, Vec2(1.0, 0.0));
    for (std::size_t b = 0; b < n; ++b) {  // velocity_ holds V at t already (prepare)
      external_[b] = inverse_mass_times(bodies[b], external_force_of(bodies[b]));  // M⁻¹ F_ext
      start_[b] = Vec3(bodies[b].x.x(), bodies[b].x.y(), planar_angle(bodies[b].q));
      bodies[b].clear_forces();
    }
    for (int step = 0; step < soft_substeps; ++step) {
      for (std::size_t b = 0; b < n; ++b) {
        if (!bodies[b].is_static()) velocity_[b] += h * external_[b];  // 1
      }
      for (const SoftRow& r : rows_) apply(r, r.impulse, velocity_);  // 2
      sweep(h, true);                                                // 3
      for (std::size_t b = 0; b < n; ++b) {                          // 4
        RigidBody& body = bodies[b];
        if (body.is_static()) continue;
        body.v = velocity_[b].head<3>();
        body.angular_velocity = velocity_[b].tail<3>();
        integrate(body, h, Integration::semi_implicit, s.step.pitfalls);
        moved_[b].head<2>() = body.x.head<2>() - start_[b].head<2>();
        // Δθ in (−π, π]: a body turning through θ = π within the step turns by a little, not 2π
        moved_[b][5] = std::remainder(planar_angle(body.q) - start_[b].z(), 2.0 * M_PI);
        turned_[b] = Vec2(std::cos(moved_[b][5]), std::sin(moved_[b][5]));
      }
      sweep(h, false);  // 5
    }
    if (s.contact.restitution) restitute(s.contact.restitution_threshold);  // 6
    for (std::size_t b = 0; b < n; ++b) {
      if (bodies[b].is_static()) continue;
      bodies[b].v = velocity_[b].head<3>();
      bodies[b].angular_velocity = velocity_[b].tail<3>();
    }
    for (std::size_t i = 0; i < rows_.size(); ++i) lambda[order_[i]] = rows_[i].impulse / h;
    if (report != nullptr) {
      report->velocity.solution.residuals = {problem.velocity.residual(lambda.data())};
    }
  }

 private:
  // Box2D v3's graph colouring, kept from step to step as v3 keeps it: a joint takes a colour
  // when it first comes, a pair when it starts touching, and keeps it while it touches; each
  // takes the lowest colour none of whose rows moves one of its moving bodies, a pair against a
  // static body never colour 0 (a joint may), and what finds none goes to the overflow. The
  // sweeps take the overflow first, then colour by colour, so that a pair against the ground
  // comes after the pairs above it (b2AddContactToGraph, b2AssignJointColor).
  void colour(const StepProblem& problem, const std::vector<RigidBody>& bodies) {
    const std::size_t n = bodies.size();
    for (auto& used : used_) used.assign(n, 0);
    const auto moving = [&](int b) { return b >= 0 && !bodies[static_cast<std::size_t>(b)].is_static(); };
    const auto mark = [&](int c, int a, int b) {
      if (c == overflow) return;
      for (int body : {a, b}) {
        if (moving(body)) used_[static_cast<std::size_t>(c)][static_cast<std::size_t>(body)] = 1;
      }
    };
    const auto take = [&](int a, int b, int first) {
      for (int c = first; c < graph_colours; ++c) {
        const auto& used = used_[static_cast<std::size_t>(c)];
        if ((moving(a) && used[static_cast<std::size_t>(a)]) || (moving(b) && used[static_cast<std::size_t>(b)])) continue;
        mark(c, a, b);
        return c;
      }
      return overflow;
    };
    // what keeps its colour: the joints coloured before (Lamina's joints are never removed) and
    // the pairs still touching; a pair that stopped touching gives its colour back
    if (joint_colours_.size() > problem.joints.size()) joint_colours_.clear();
    for (std::size_t j = 0; j < joint_colours_.size(); ++j) {
      const std::array<int, 2> jb = problem.joints[j]->bodies();
      mark(joint_colours_[j], jb[0], jb[1]);
    }
    // problem.pairs and the colours kept from the last step are both in pair order: one walk
    // finds each pair's colour of before, or none (a pair that just started touching)
    constexpr int uncoloured = -1;  // no colour yet (colours are 0 … graph_colours − 1, or the overflow)
    next_colours_.clear();
    std::size_t before = 0;
    for (const ContactPair& pair : problem.pairs) {
      while (before < pair_colours_.size() && pair_colours_[before].first < pair.bodies) ++before;
      const bool kept = before < pair_colours_.size() && pair_colours_[before].first == pair.bodies;
      next_colours_.emplace_back(pair.bodies, kept ? pair_colours_[before].second : uncoloured);
      if (kept) mark(pair_colours_[before].second, pair.bodies.first, pair.bodies.second);
    }
    pair_colours_.swap(next_colours_);
    // what is new takes one: the joints (v3 colours a joint when it is made, before any contact
    // of the first step), then the pairs that started touching, in the World's pair order
    for (std::size_t j = joint_colours_.size(); j < problem.joints.size(); ++j) {
      const std::array<int, 2> jb = problem.joints[j]->bodies();
      joint_colours_.push_back(take(jb[0], jb[1], 0));
    }
    for (auto& [bodies_of_pair, colour] : pair_colours_) {
      if (colour != uncoloured) continue;
      const bool against_static = !moving(bodies_of_pair.first) || !moving(bodies_of_pair.second);
      colour = take(bodies_of_pair.first, bodies_of_pair.second, against_static ? 1 : 0);
    }
  }

  // The rows as the sweeps take them: the overflow's joints' rows and pairs' rows, then colour
  // by colour its joints' rows and its pairs' rows, each pair's contact rows before its friction
  // rows (Box2D v3's order), with their separations at t and softness.
  void prepare(const StepProblem& problem, const std::vector<RigidBody>& bodies,
               const std::vector<double>& lambda, double h, const Softness& contact,
               const Softness& against_static, const Softness& joint) {
    const Mlcp& mlcp = problem.velocity;
    const int count = mlcp.row_count();
    rows_.assign(static_cast<std::size_t>(count), SoftRow());
    // each row's place in the sweep: 2 c for the joints of colour c (the overflow as −1), 2 c + 1
    // for its pairs
    std::vector<int>& place = place_;
    place.assign(static_cast<std::size_t>(count), 0);
    const auto rank = [](int c) { return c == overflow ? -1 : c; };
    for (std::size_t j = 0; j < problem.joints.size(); ++j) {
      const RowRange& range = problem.joint_rows[j];
      for (int i = range.first; i < range.first + range.count; ++i) {
        place[static_cast<std::size_t>(i)] = 2 * rank(joint_colours_[j]);
      }
    }
    for (std::size_t k = 0; k < problem.pairs.size(); ++k) {
      const ContactPair& pair = problem.pairs[k];
      const int c = pair_colours_[k].second;  // colour() kept them in pair order
      for (int i = pair.rows.first; i < pair.rows.first + pair.rows.count; ++i) {
        place[static_cast<std::size_t>(i)] = 2 * rank(c) + 1;
      }
    }
    // the rows in order of place, rows of one place in the MLCP's order: a counting sort over the
    // places −2 … 2 graph_colours − 1 (stable, and in buffers kept from step to step)
    const auto bucket = [](int p) { return static_cast<std::size_t>(p + 2); };
    starts_.assign(2 * graph_colours + 3, 0);
    for (int p : place) ++starts_[bucket(p) + 1];
    for (std::size_t k = 1; k < starts_.size(); ++k) starts_[k] += starts_[k - 1];
    order_.resize(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
      order_[starts_[bucket(place[static_cast<std::size_t>(i)])]++] = static_cast<std::size_t>(i);
    }
    std::vector<int>& position = position_;
    position.resize(static_cast<std::size_t>(count));
    for (std::size_t k = 0; k < order_.size(); ++k) position[order_[k]] = static_cast<int>(k);
    // The joints' separations at t: their rows written with β = 1 ask ζ = −C/Δt of both kinds
    // (eq. 3-14, 3-17..3-19), so C = −ζ Δt.
    written_.clear();
    for (const Constraint* j : problem.joints) j->write_rows(bodies, problem.settings.step.dt, 1.0, written_);
    const int first_joint = static_cast<int>(problem.first_joint_row);
    for (int i = 0; i < count; ++i) {
      SoftRow& r = rows_[static_cast<std::size_t>(position[static_cast<std::size_t>(i)])];
      r.bodies = mlcp.bodies_of(i);
      for (int k = 0; k < 2; ++k) {
        r.J[static_cast<std::size_t>(k)] = mlcp.jacobian(i, k);
        r.B[static_cast<std::size_t>(k)] = mlcp.b_block(i, k);
      }
      r.mass = 1.0 / mlcp.d(i);
      r.impulse = lambda[static_cast<std::size_t>(i)] * h;  // the warm start, P = λ h
      if (i >= first_joint) {
        const double none = 0.0;  // a joint's row has fixed bounds: λ is not read
        r.kind = std::isinf(mlcp.bounds(i, &none)[0]) ? Kind::joint : Kind::joint_limit;
        r.separation = -written_[static_cast<std::size_t>(i - first_joint)].zeta * problem.settings.step.dt;
        r.softness = joint;
      } else if (mlcp.friction_of(i) >= 0) {
        r.kind = Kind::friction;
        r.friction_of = position[static_cast<std::size_t>(mlcp.friction_of(i))];
        r.friction_count = mlcp.friction_count(i);
        r.mu = mlcp.mu(i);
      } else {
        r.kind = Kind::contact;
        r.softness = r.bodies[1] < 0 ? against_static : contact;
      }
    }
    // v3's coloured contacts cap the push-out at 3 m/s over the static softness's s_m, which the
    // s_m of the solve takes back to 3 m/s against the ground; its overflow contacts at 3 m/s
    const double coloured_push = push_out_speed / against_static.mass_scale;
    for (std::size_t p = 0; p < problem.pairs.size(); ++p) {
      const ContactPair& pair = problem.pairs[p];
      const bool overflowed = pair_colours_[p].second == overflow;
      for (int k = 0; k < pair.count; ++k) {
        const Contact& c = pair.contacts[k];
        SoftRow& r = rows_[static_cast<std::size_t>(position[static_cast<std::size_t>(c.row)])];
        r.separation = c.separation;
        r.restitution = pair.restitution;
        r.max_push = overflowed ? push_out_speed : coloured_push;
        for (std::size_t e = 0; e < 2; ++e) {  // r_k = c − x_k, as the row's J was written
          if (r.bodies[e] >= 0) r.lever[e] = c.point - bodies[static_cast<std::size_t>(r.bodies[e])].x.head<2>();
        }
      }
    }
    velocity_.resize(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) velocity_[b] = velocity_of(bodies[b]);
    for (SoftRow& r : rows_) r.approach = dot_row(r, velocity_);
  }

  // A row's separation now. A contact's, as Box2D v3 takes it: its points ride on their bodies
  // with the levers r_k fixed at t, C = C₀ + Σ_k n_k · (Δx_k + R(Δθ_k) r_k − r_k), n_k = ±n
  // the linear part of J_k (eq. 4-1 at the moved poses, the normal held). A joint's to first
  // order, C = C₀ + J Δq.
  double separation_now(const SoftRow& r) const {
    if (r.kind != Kind::contact) return r.separation + dot_row(r, moved_);
    double C = r.separation;
    for (std::size_t e = 0; e < 2; ++e) {
      if (r.bodies[e] < 0) continue;
      const auto b = static_cast<std::size_t>(r.bodies[e]);
      const Vec2& a = r.lever[e];
      const Vec2& cs = turned_[b];  // cos Δθ, sin Δθ
      const Vec2 turned(cs.x() * a.x() - cs.y() * a.y(), cs.y() * a.x() + cs.x() * a.y());
      C += r.J[e].head<2>().dot(moved_[b].head<2>() + turned - a);
    }
    return C;
  }

  // One sweep over the rows: with the soft bias (solve) or without it, rigid (relax).
  void sweep(double h, bool bias) {
    for (SoftRow& r : rows_) {
      const double v = dot_row(r, velocity_);
      double delta = 0.0;
      if (r.kind == Kind::friction) {
        double normal = 0.0;
        for (int k = 0; k < r.friction_count; ++k) normal += rows_[static_cast<std::size_t>(r.friction_of + k)].impulse;
        const double limit = r.mu * normal;  // eq. 3-26, on impulses
        const double next = std::clamp(r.impulse - r.mass * v, -limit, limit);
        delta = next - r.impulse;
      } else {
        const double C = separation_now(r);
        const bool one_sided = r.kind != Kind::joint;
        double velocity_bias = 0.0, mass_scale = 1.0, impulse_scale = 0.0;
        if (one_sided && C > 0.0) {
          velocity_bias = C / h;  // an open gap may close within the substep
        } else if (bias) {
          velocity_bias = r.softness.bias_rate * C;
          if (r.kind == Kind::contact) velocity_bias = std::max(velocity_bias, -r.max_push);
          mass_scale = r.softness.mass_scale;
          impulse_scale = r.softness.impulse_scale;
        }
        delta = -r.mass * mass_scale * (v + velocity_bias) - impulse_scale * r.impulse;
        if (one_sided) delta = std::max(r.impulse + delta, 0.0) - r.impulse;
      }
      r.impulse += delta;
      r.total += r.impulse;
      apply(r, delta, velocity_);
    }
  }

  // Box2D v3's restitution, after the substeps: a contact that approached faster than the
  // threshold and pushed in any sweep of the step leaves at e times its approach speed.
  void restitute(double threshold) {
    for (SoftRow& r : rows_) {
      if (r.kind != Kind::contact || r.restitution == 0.0) continue;
      if (r.approach > -threshold || r.total == 0.0) continue;
      const double v = dot_row(r, velocity_);
      const double next = std::max(r.impulse - r.mass * (v + r.restitution * r.approach), 0.0);
      apply(r, next - r.impulse, velocity_);
      r.impulse = next;
    }
  }

  std::vector<SoftRow> rows_;          // in sweep order
  std::vector<std::size_t> order_;     // rows_[k] is the MLCP's row order_[k]
  std::vector<ConstraintRow> written_; // the joints' rows written with β = 1
  std::vector<Vec6> velocity_;         // each body's [v; ω]
  std::vector<Vec6> external_;         // M⁻¹ F_ext per body
  std::vector<Vec3> start_;            // each body's x, y and θ at t
  std::vector<Vec6> moved_;            // how far each body has moved since t, [Δx; Δθ ẑ]
  std::vector<Vec2> turned_;           // cos Δθ, sin Δθ of each body since t
  std::array<std::vector<char>, graph_colours> used_;  // colour c moves body b: used_[c][b]
  std::vector<int> joint_colours_;     // each joint's colour (or the overflow), in joint order
  // each touching pair's colour (or the overflow), in the pairs' order, and the next step's,
  // kept to reuse their memory
  std::vector<std::pair<BodyPair, int>> pair_colours_, next_colours_;
  std::vector<int> place_;             // each row's place in the sweep order (prepare)
  std::vector<std::size_t> starts_;    // where each place's rows start in order_ (prepare)
  std::vector<int> position_;          // each MLCP row's index in rows_ (prepare)
};

}  // namespace

std::unique_ptr<StepMethod> make_soft_step_method() { return std::make_unique<SoftStep>(); }

}  // namespace lamina
