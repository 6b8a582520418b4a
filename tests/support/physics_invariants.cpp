#include "support/physics_invariants.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include <Eigen/LU>

#include "beyond/soft_step.h"
#include "constraints/dense_system.h"
#include "constraints/exact_mlcp.h"
#include "constraints/pgs_solver.h"
#include "scene/scene_json.h"
#include "scene/scene_world.h"

namespace lamina::fuzz {
namespace {

// Round-off in the bounds: PGS clamps λ_t to ±μ λ_n exactly, the exact and block solvers to the
// rounding of their pivots and 2 × 2 solves, relative to the step's largest force; Lemke's answer
// is checked row by row to 1e-9 of max(1, the row's scale) (lemke.cpp), so below 1e-9 N a force
// is round-off (found: |λ_t| = 1.3e-12 N against μ λ_n = 0 where every force of the step was
// below 5e-12 N).
constexpr double bound_relative = 1e-9;
constexpr double bound_absolute = 1e-9;  // in N
// Lemke's pivots (`exact`, and `islands` on small islands) on the wide kind's MLCPs, whose masses
// differ by up to 1e8 and sizes by 1e7, lose digits as the condition number grows (found: a
// friction λ 1.2e-7 of the step's force scale past its bound of 0): 1e-6 for them.
constexpr double pivoting_relative = 1e-6;
// PGS is run to ‖W‖ ≤ this (relative to ‖η‖) before its λ is compared with the exact one, and
// the two must then agree to exact_tolerance relative to max(1, |λ_exact|∞).
constexpr double pgs_converged = 1e-12;
constexpr int pgs_sweeps = 20000;
constexpr double exact_tolerance = 1e-6;

// A number for a message, to 6 significant digits (forces span 1e-6 to 1e12 N).
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string at_step(long step, const std::string& what) {
  return "step " + std::to_string(step) + ": " + what;
}

// The first planar component that is not exactly 0, or nothing.
std::optional<std::string> off_plane(const World& world) {
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const RigidBody& b = world.bodies()[i];
    if (b.x.z() != 0.0 || b.v.z() != 0.0 || b.angular_velocity.x() != 0.0 ||
        b.angular_velocity.y() != 0.0 || b.q.x() != 0.0 || b.q.y() != 0.0) {
      return "body " + std::to_string(i) + " left the x–y plane";
    }
  }
  return std::nullopt;
}

// μ of each pair, from the scene's own friction values (√(μ1 μ2), shape.h's rule).
double pair_friction(const Scene& scene, const BodyPair& pair) {
  return std::sqrt(scene.bodies[pair.first].friction * scene.bodies[pair.second].friction);
}

std::optional<std::string> out_of_bounds(const Scene& scene, const World& world,
                                         const WorldReport& step, long& checked) {
  const std::vector<ContactInfo> contacts = world.contacts();
  // The step's force scale: its largest λ, or the largest force that would stop a row alone,
  // |η_i| / d_i (eq. 3-24's Gauss-Seidel step from λ = 0). The exact solvers round relative to
  // it, and a scene's forces span from 1e-12 N to 1e12 N within the reader's ranges.
  double largest = 0.0;
  for (const ContactInfo& c : contacts) {
    largest = std::max({largest, std::abs(c.lambda_normal), std::abs(c.lambda_tangent)});
  }
  const Mlcp& mlcp = step.velocity.mlcp;
  for (int i = 0; i < mlcp.row_count(); ++i) {
    if (mlcp.d(i) > 0.0) largest = std::max(largest, std::abs(mlcp.eta(i)) / mlcp.d(i));
  }
  const bool pivoting = scene.solver == "exact" || scene.solver == "islands";
  const double tolerance = (pivoting ? pivoting_relative : bound_relative) * largest + bound_absolute;
  for (const ContactInfo& c : contacts) {
    ++checked;
    const double mu = pair_friction(scene, c.bodies);
    const double n = c.lambda_normal, t = c.lambda_tangent;
    if (n < -tolerance) return "contact λ_n = " + number(n) + " N < 0";
    if (std::abs(t) > mu * n + tolerance) {
      return "friction |λ_t| = " + number(std::abs(t)) + " N > μ λ_n = " + number(mu * n) +
             " N (μ = " + number(mu) + ", the step's largest force " + number(largest) + " N)";
    }
  }
  return std::nullopt;
}

double moving_mass(const World& world) {
  double mass = 0.0;
  for (const RigidBody& b : world.bodies()) {
    if (!b.is_static()) mass += b.mass;
  }
  return mass;
}

// Σ_c max(0, d_c − slop) over the contacts the last step solved (d = −C at t), in m.
double corrected_depth(const World& world) {
  double sum = 0.0;
  for (const ContactInfo& c : world.contacts()) {
    sum += std::max(0.0, -c.separation - world.settings().contact.slop);
  }
  return sum;
}

// PGS to convergence beside Lemke on the velocity MLCP of one more step, when J B has full rank
// (then λ is unique wherever both find one).
void compare_with_exact(World& world, InvariantReport& report) {
  WorldReport step;
  world.step(step);
  const Mlcp& mlcp = step.velocity.mlcp;
  const int rows = mlcp.row_count();
  if (rows == 0 || !has_exact_form(mlcp)) return;
  const Eigen::MatrixXd JB = dense_jacobian(mlcp) * dense_b_transpose(mlcp).transpose();
  Eigen::FullPivLU<Eigen::MatrixXd> lu(JB);
  lu.setThreshold(1e-9);
  if (lu.rank() < rows) return;
  const ExactSolution exact = solve_mlcp_exactly(mlcp);
  if (exact.status != LemkeStatus::solved) return;
  SweepSettings settings;
  settings.iterations = pgs_sweeps;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(rows);
  const double scale = std::max(1.0, mlcp.slack(zero.data()).norm());  // ‖η‖, W at λ = 0
  settings.tolerance = pgs_converged * scale;
  const SweepResult pgs = solve_pgs(mlcp, zero, settings);
  if (mlcp.residual(pgs.lambda.data()) > settings.tolerance) return;
  report.compared_exact = true;
  report.exact_difference = (pgs.lambda - exact.lambda).cwiseAbs().maxCoeff() /
                            std::max(1.0, exact.lambda.cwiseAbs().maxCoeff());
  if (report.exact_difference > exact_tolerance) {
    report.violation = "exact: PGS's λ differs from the exact solution's by " +
                       std::to_string(report.exact_difference) + " (relative)";
  }
}

// How far a body moved from `from` to `to`: sideways, up, down, and the turn, in m and rad.
struct Move {
  double sideways, up, down, turn;
};
Move move_between(const RigidBody& from, const RigidBody& to) {
  const Vec3 d = to.x - from.x;
  return {std::abs(d.x()), std::max(d.y(), 0.0), std::max(-d.y(), 0.0),
          std::abs(std::remainder(planar_angle(to.q) - planar_angle(from.q), 2.0 * M_PI))};
}

std::string described(const Move& m, const char* when) {
  return std::string(when) + " it moved " + std::to_string(m.sideways) + " m sideways, " +
         std::to_string(m.up) + " m up, " + std::to_string(m.down) + " m down and turned " +
         std::to_string(m.turn) + " rad";
}

// The resting body: over the whole run it settles — sideways and up at most creep_distance or,
// rocking on its face without tipping, half the face; down at most the slop and creep_distance;
// turned at most creep_angle or the angle it would tip at, atan(face/2 ÷ height) — and over the
// second half it moves a tenth of that at most: it settles, it does not creep. The text's
// method and soft-step take a flat face's first contact at a corner and tip onto it first: for
// them corner_first_distance and corner_first_angle.
std::optional<std::string> settled(const RigidBody& start, const RigidBody& halfway,
                                   const RigidBody& end, const World& world,
                                   const GeneratedScene& generated) {
  const bool corner_first = generated.scene.solver == "text" || generated.scene.solver == "soft-step";
  const double half_face = 0.5 * generated.face.length;
  const double rock_angle = std::atan2(half_face, generated.face.height);
  const double distance = corner_first ? corner_first_distance : std::max(creep_distance, half_face);
  const double angle = corner_first ? corner_first_angle : std::max(creep_angle, rock_angle);
  const double slop = world.settings().contact.slop;
  const Move whole = move_between(start, end);
  // tipping onto a corner lifts the centre too (by about half the face times the turn)
  const double up = corner_first ? corner_first_distance : creep_distance;
  if (whole.sideways > distance || whole.up > up || whole.down > slop + creep_distance ||
      whole.turn > angle) {
    return described(whole, "over the run");
  }
  const Move late = move_between(halfway, end);
  if (late.sideways > distance / 10 || late.up > creep_distance / 10 ||
      late.down > creep_distance / 10 || late.turn > angle / 10) {
    return described(late, "over the second half of the run (creeping)");
  }
  return std::nullopt;
}

}  // namespace

InvariantReport check_invariants(const GeneratedScene& generated) {
  InvariantReport report;
  const std::string text = scene_to_json(generated.scene);
  Scene scene;
  try {
    scene = parse_scene(text, "generated.json");
  } catch (const SceneError& e) {
    report.violation = std::string("reader: refused a generated scene: ") + e.what();
    return report;
  }
  if (scene_to_json(scene) != text) {
    report.violation = "reader: the generated scene does not read back as itself";
    return report;
  }
  std::optional<World> built;
  try {
    built.emplace(build_world(scene, world_settings(scene)));
  } catch (const std::invalid_argument& e) {
    report.violation = std::string("engine: refused a scene the reader accepts: ") + e.what();
    return report;
  }
  World& world = *built;
  report.built = true;

  // soft-step clamps friction to μ times the normal impulse of the moment it is swept (Box2D v3's
  // order); its relax and restitution sweeps change the normal impulse afterwards, so its final
  // λ need not keep the MLCP's bounds (measured: |λ_t| 3.16 N against μ λ_n = 0.057 N)
  const bool bounds_apply = scene.solver != "soft-step";
  const bool energy_applies = generated.passive && scene.joints.empty();
  const double mass = moving_mass(world);                                 // M, kg
  const double weight = mass * world.settings().step.gravity.norm();      // M |g|, N
  // How fast a bias may push bodies apart per metre of penetration beyond the slop, in 1/s:
  // Baumgarte's β/Δt (eq. 4-4), soft-step's soft bias rate, at most 1/h for its substep h
  // (Box2D v3's ω/(2ζ + hω) < 1/h); split impulse moves positions only, giving no velocity.
  const double push_rate =
      scene.solver == "soft-step" ? soft_substeps / scene.step.dt
      : world.settings().contact.correction == PositionCorrection::baumgarte
          ? scene.step.beta / scene.step.dt
          : 0.0;
  const double start_energy = mechanical_energy(world);
  const double energy_round_off = 1e-9 * (std::abs(start_energy) + weight * 10.0);
  // ½ M (|g| Δt)², the warm start's allowance, then Σ_k ΔE_k as the run goes, in J
  const double impulse = weight * scene.step.dt;  // M |g| Δt, in N·s
  double allowed = mass > 0.0 ? 0.5 * impulse * impulse / mass : 0.0;
  report.energy_margin = std::numeric_limits<double>::infinity();
  std::map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) index_of[scene.bodies[i].name] = i;
  const std::optional<RigidBody> rest =
      generated.resting.empty() ? std::nullopt
                                : std::optional<RigidBody>(world.bodies()[index_of.at(generated.resting)]);

  std::optional<RigidBody> halfway;  // the resting body halfway through the run
  WorldReport step_report;  // what the step solved: the bounds' scale reads its MLCP
  for (long step = 0; step < generated.steps; ++step) {
    world.step(step_report);
    report.steps = step + 1;
    if (rest && step + 1 == generated.steps / 2) {
      halfway = world.bodies()[index_of.at(generated.resting)];
    }
    if (world.first_non_finite_body()) {
      report.violation = at_step(step, "finite: a body's state is no longer finite");
      return report;
    }
    if (std::optional<std::string> off = off_plane(world)) {
      report.violation = at_step(step, "planar: " + *off);
      return report;
    }
    if (bounds_apply) {
      if (std::optional<std::string> bad = out_of_bounds(scene, world, step_report, report.bound_checks)) {
        report.violation = at_step(step, "bounds: " + *bad);
        return report;
      }
    }
    if (energy_applies) {
      // ΔE_k = M |g| D + (Baumgarte) ½ M (β D / Δt)², D = Σ_c max(0, d_c − slop)
      const double depth = corrected_depth(world);
      allowed += weight * depth;
      if (push_rate > 0.0) {
        const double push = push_rate * depth;  // the bias velocity's bound, in m/s
        allowed += 0.5 * mass * push * push;
      }
      const double gain = mechanical_energy(world) - start_energy;
      report.largest_gain = std::max(report.largest_gain, gain);
      report.energy_margin = std::min(report.energy_margin, allowed - gain);
      if (gain > allowed + energy_round_off) {
        report.violation = at_step(step, "energy: E − E0 = " + std::to_string(gain) +
                                             " J above the " + std::to_string(allowed) +
                                             " J that undoing penetration may add");
        return report;
      }
    }
  }
  if (rest) {
    const RigidBody& end = world.bodies()[index_of.at(generated.resting)];
    if (std::optional<std::string> moved = settled(*rest, *halfway, end, world, generated)) {
      report.violation = "resting: " + *moved;
      return report;
    }
  }
  if (generated.kind == SceneKind::island) compare_with_exact(world, report);
  return report;
}

}  // namespace lamina::fuzz
