#include "beyond/soft_step.h"

#include <algorithm>
#include <array>
#include <cmath>
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

enum class Kind { contact, friction, joint, joint_limit };

// One row as the soft step sweeps it.
struct SoftRow {
  Kind kind = Kind::contact;
  std::array<int, 2> bodies{-1, -1};
  std::array<Vec6, 2> J, B;  // J_i's and B_i's blocks
  double mass = 0.0;         // 1/d_i
  double separation = 0.0;   // C at t, in m (contacts, joints)
  Softness softness;
  int friction_of = -1, friction_count = 0;  // a friction row's contact rows
  double mu = 0.0;
  double restitution = 0.0;  // e of a contact row's pair
  double approach = 0.0;     // J V at t, in m/s (restitution)
  double impulse = 0.0;      // P, in N·s
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
    static_mass_scale_ = against_static.mass_scale;
    prepare(problem, bodies, lambda, h, contact, against_static, joint);

    const std::size_t n = bodies.size();
    external_.resize(n);
    start_.resize(n);
    moved_.assign(n, Vec6::Zero());
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
        moved_[b][5] = planar_angle(body.q) - start_[b].z();
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
  // The rows as the sweeps take them: the joints' first, then each pair's contact and friction
  // rows (Box2D v3's order), with their separations at t and softness.
  void prepare(const StepProblem& problem, const std::vector<RigidBody>& bodies,
               const std::vector<double>& lambda, double h, const Softness& contact,
               const Softness& against_static, const Softness& joint) {
    const Mlcp& mlcp = problem.velocity;
    const int count = mlcp.row_count();
    rows_.assign(static_cast<std::size_t>(count), SoftRow());
    order_.clear();
    const int first_joint = static_cast<int>(problem.first_joint_row);
    for (int i = first_joint; i < count; ++i) order_.push_back(static_cast<std::size_t>(i));
    for (int i = 0; i < first_joint; ++i) order_.push_back(static_cast<std::size_t>(i));
    std::vector<int> position(static_cast<std::size_t>(count));
    for (std::size_t k = 0; k < order_.size(); ++k) position[order_[k]] = static_cast<int>(k);
    // The joints' separations at t: their rows written with β = 1 ask ζ = −C/Δt of both kinds
    // (eq. 3-14, 3-17..3-19), so C = −ζ Δt.
    written_.clear();
    for (const Constraint* j : problem.joints) j->write_rows(bodies, problem.settings.step.dt, 1.0, written_);
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
    for (const ContactPair& pair : problem.pairs) {
      for (int k = 0; k < pair.count; ++k) {
        SoftRow& r = rows_[static_cast<std::size_t>(position[static_cast<std::size_t>(pair.contacts[k].row)])];
        r.separation = pair.contacts[k].separation;
        r.restitution = pair.restitution;
      }
    }
    velocity_.resize(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) velocity_[b] = velocity_of(bodies[b]);
    for (SoftRow& r : rows_) r.approach = dot_row(r, velocity_);
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
        const double C = r.separation + dot_row(r, moved_);  // to first order in Δq
        const bool one_sided = r.kind != Kind::joint;
        double velocity_bias = 0.0, mass_scale = 1.0, impulse_scale = 0.0;
        if (one_sided && C > 0.0) {
          velocity_bias = C / h;  // an open gap may close within the substep
        } else if (bias) {
          // a contact's bias as Box2D v3's SIMD contact solver takes it: b scaled by s_m, and
          // the push-out capped at 3 m/s over the static softness's s_m
          velocity_bias = one_sided ? std::max(r.softness.mass_scale * r.softness.bias_rate * C,
                                               -push_out_speed / static_mass_scale_)
                                    : r.softness.bias_rate * C;
          mass_scale = r.softness.mass_scale;
          impulse_scale = r.softness.impulse_scale;
        }
        delta = -r.mass * mass_scale * (v + velocity_bias) - impulse_scale * r.impulse;
        if (one_sided) delta = std::max(r.impulse + delta, 0.0) - r.impulse;
      }
      r.impulse += delta;
      apply(r, delta, velocity_);
    }
  }

  // Box2D v3's restitution, after the substeps: a contact that approached faster than the
  // threshold and pushes leaves at e times its approach speed.
  void restitute(double threshold) {
    for (SoftRow& r : rows_) {
      if (r.kind != Kind::contact || r.restitution == 0.0) continue;
      if (r.approach > -threshold || r.impulse == 0.0) continue;
      const double v = dot_row(r, velocity_);
      const double next = std::max(r.impulse - r.mass * (v + r.restitution * r.approach), 0.0);
      apply(r, next - r.impulse, velocity_);
      r.impulse = next;
    }
  }

  double static_mass_scale_ = 1.0;     // s_m of the contacts against a static body
  std::vector<SoftRow> rows_;          // in sweep order
  std::vector<std::size_t> order_;     // rows_[k] is the MLCP's row order_[k]
  std::vector<ConstraintRow> written_; // the joints' rows written with β = 1
  std::vector<Vec6> velocity_;         // each body's [v; ω]
  std::vector<Vec6> external_;         // M⁻¹ F_ext per body
  std::vector<Vec3> start_;            // each body's x, y and θ at t
  std::vector<Vec6> moved_;            // how far each body has moved since t, [Δx; Δθ ẑ]
};

}  // namespace

std::unique_ptr<StepMethod> make_soft_step_method() { return std::make_unique<SoftStep>(); }

}  // namespace lamina
