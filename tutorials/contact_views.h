// What the chapter 4 and 5 tutorials share: a contact World seen one step ahead, its bodies and
// contacts as the renderer draws them, and its step explained row by row (--explain).
// Header-only, so that each tutorial links lamina::contact and the harness only.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "constraints/dense_system.h"
#include "contact/world.h"
#include "harness/body_view.h"
#include "harness/explanation.h"
#include "render/frame.h"

namespace lamina::tutorial {

// A World shown at t together with what its step from t solved: a frame draws the bodies where
// the contacts were found, with the λ the solver gave them (the text's walk-through reads the
// same way: "at t = τ the MLCP gives λ1").
class SolvedWorld {
 public:
  explicit SolvedWorld(const WorldSettings& settings) : world_(settings) {}

  // The world, to add bodies before the first solve().
  World& world() { return world_; }
  const World& world() const { return world_; }

  // Keeps the bodies at t, then steps t → t + Δt, recording what the step solved.
  void solve() {
    at_t_ = world_.bodies();
    world_.step(report_);
  }

  const std::vector<RigidBody>& bodies() const { return at_t_; }  // the bodies at t
  const WorldReport& report() const { return report_; }           // the step from t

 private:
  World world_;
  std::vector<RigidBody> at_t_;
  WorldReport report_;
};

// Body i of a solved world at t, drawn with its shape.
inline render::Body body_view(const SolvedWorld& w, int i, render::Colour fill) {
  const RigidBody& b = w.bodies().at(static_cast<std::size_t>(i));
  const Shape& shape = w.world().shape(i);
  render::Body view = box_view(b, shape.half_extents, fill);
  if (!shape.is_box()) {
    view.shape = render::Body::Shape::circle;
    view.radius = shape.radius;
  }
  return view;
}

// A contact as drawn: point, normal, λ of its contact row along n, of its friction row along
// u1 = z × n (chapter 4: the force on body 2 is λ_n n + λ_t u1).
inline render::Contact contact_view(const ContactInfo& c) {
  render::Contact view;
  view.point = c.point.head<2>();
  view.normal = c.normal.head<2>();
  view.tangent = render::Vec2(-c.normal.y(), c.normal.x());
  view.normal_force = c.lambda_normal;
  view.friction_force = c.lambda_tangent;
  view.cached = c.cached;
  return view;
}

inline const char* row_kind_name(RowKind kind) {
  switch (kind) {
    case RowKind::contact: return "contact row (eq. 4-3)";
    case RowKind::friction: return "friction row along u1 = z × n";
    case RowKind::out_of_plane_friction: return "friction row along u2 = z";
    case RowKind::joint: return "joint row";
  }
  return "row";
}

inline Json json_of(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    Json row = Json::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
    rows.push_back(row);
  }
  return rows;
}

inline Json json_of(const Eigen::VectorXd& v) {
  Json values = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) values.push_back(v[i]);
  return values;
}

// "[0, +∞)" and the like: the bounds of a row as solved (a friction row's are ±μ λc).
inline std::string bounds_text(const std::array<double, 2>& b) {
  auto end = [](double x) {
    if (std::isinf(x)) return std::string(x > 0 ? "+∞" : "−∞");
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x == 0.0 ? 0.0 : x);
    return std::string(text);
  };
  return "[" + end(b[0]) + ", " + end(b[1]) + (std::isinf(b[1]) ? ")" : "]");
}

// What the step from t solved, in the text's terms: bodies, contacts, each row of the velocity
// MLCP (J, ζ, η, d, bounds, λ_exp, λ, W), the PGS residual per sweep, and for small systems the
// dense J, M⁻¹ and J M⁻¹ Jᵀ.
inline Explanation explain_solved(const SolvedWorld& w) {
  const std::vector<RigidBody>& bodies = w.bodies();
  const WorldReport& report = w.report();
  const StepReport& velocity = report.velocity;
  const Vec3 gravity = w.world().settings().gravity;
  Explanation e;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBody& b = bodies[i];
    if (b.is_static()) continue;
    e.push_back({"body " + std::to_string(i) + " at t",
                 {{"x", "", "centre of mass", json_of(b.x), "m"},
                  {"θ", "", "angle about z", planar_angle(b.q), "rad"},
                  {"v", "5-3", "velocity", json_of(b.v), "m/s"},
                  {"ω", "5-3", "angular velocity", json_of(b.angular_velocity), "rad/s"},
                  {"m⁻¹", "5-1", "inverse mass", b.inverse_mass, "1/kg"},
                  {"I⁻¹", "5-1", "inverse inertia R I0⁻¹ Rᵀ", json_of(b.inverse_inertia_world),
                   "1/(kg·m²)"},
                  {"F_ext", "5-2", "m g", json_of(Vec3(b.mass * gravity)), "N"}}});
  }
  for (std::size_t k = 0; k < report.contacts.size(); ++k) {
    const ContactInfo& c = report.contacts[k];
    e.push_back({"contact " + std::to_string(k) + ": bodies (" + std::to_string(c.bodies.first) +
                     ", " + std::to_string(c.bodies.second) + "), " +
                     (c.cached ? "cached (re-placed, eq. 5-12)" : "fresh (deepest point, Fig 4-2)"),
                 {{"c", "4-1", "contact point", json_of(c.point), "m"},
                  {"n", "4-1", "normal from body 1 to body 2", json_of(c.normal), ""},
                  {"C", "4-1, 5-6", "separation (negative: penetration ε)", c.separation, "m"},
                  {"λ_n", "4-3", "contact row's λ (impulse λ Δt)", c.lambda_normal, "N"},
                  {"λ_t", "", "friction row's λ along u1", c.lambda_tangent, "N"}}});
  }
  const Mlcp& mlcp = velocity.mlcp;
  const Eigen::VectorXd& lambda = velocity.solution.lambda;
  const Eigen::MatrixXd J = dense_jacobian(mlcp.rows, mlcp.body_count);
  for (std::size_t i = 0; i < mlcp.rows.size(); ++i) {
    const ConstraintRow& row = mlcp.rows[i];
    const auto r = static_cast<Eigen::Index>(i);
    const std::string second = row.is_one_body() ? "none" : std::to_string(row.Jmap[1]);
    e.push_back(
        {"row " + std::to_string(i) + ": " + row_kind_name(report.kinds.at(i)) + ", bodies (" +
             std::to_string(row.Jmap[0]) + ", " + second + ")",
         {{"J_i", "3-8, 4-3", "the row over [v ω] of every body", json_of(Eigen::VectorXd(J.row(r))),
           ""},
          {"ζ_i", "4-4, 4-5", "velocity asked of J V(t+Δt)", row.zeta, "m/s"},
          {"η_i", "3-16", "ζ/Δt − J (V/Δt + M⁻¹ F_ext)", mlcp.eta[r], "m/s²"},
          {"d_i", "3-16", "J_i B_i, diagonal of J M⁻¹ Jᵀ", mlcp.d[r], ""},
          {"[λ⁻, λ⁺]", "3-24, 3-26", "bounds as solved (friction: ±μ λc)",
           bounds_text(row_bounds(row, lambda)), "N"},
          {"λ_exp", "", "warm start (the cached λ)", velocity.lambda_exp[r], "N"},
          {"λ_i", "3-24", "PGS's answer", lambda[r], "N"},
          {"W_i", "3-23", "(J B λ − η)_i", velocity.W[r], "m/s²"}}});
  }
  if (!mlcp.rows.empty()) {
    Json residuals = Json::array();
    for (double x : velocity.solution.residuals) residuals.push_back(x);
    e.push_back({"PGS (eq. 3-24)",
                 {{"sweeps", "", "Gauss-Seidel sweeps run", velocity.solution.iterations, ""},
                  {"‖W‖", "3-23", "MLCP residual after each sweep", residuals, "m/s²"}}});
  }
  constexpr Eigen::Index small = 4;  // rows up to which the dense matrices are printed
  if (!mlcp.rows.empty() && static_cast<Eigen::Index>(mlcp.rows.size()) <= small &&
      mlcp.body_count <= 2) {
    const Eigen::MatrixXd JB = J * dense_b_transpose(mlcp).transpose();
    e.push_back({"dense system (small)",
                 {{"J", "3-8", "s × 6n Jacobian", json_of(J), ""},
                  {"M⁻¹", "3-12, 5-1", "diag(m⁻¹E, I⁻¹) per body, 0 for the ground",
                   json_of(dense_inverse_mass(bodies)), ""},
                  {"J M⁻¹ Jᵀ", "3-16", "the MLCP's matrix J B", json_of(JB), ""}}});
  }
  return e;
}

}  // namespace lamina::tutorial
