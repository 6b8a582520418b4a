#include "constraints/text_pgs.h"

#include <algorithm>

namespace lamina::text {
namespace {

// M⁻¹ of one body: diag(m⁻¹ E, I⁻¹) (eq. 3-12).
Matrix6x6 inverse_mass_block(const RigidBody& body) {
  Matrix6x6 block = Matrix6x6::Zero();
  block.topLeftCorner<3, 3>() = body.inverse_mass * Mat3::Identity();
  block.bottomRightCorner<3, 3>() = body.inverse_inertia_world;
  return block;
}

// V/Δt + M⁻¹ F_ext of one body, the bracket of η (eq. 3-5, 3-9, 3-16).
Vector6 unconstrained_velocity(const RigidBody& body, const Matrix6x6& M_inverse, double dt) {
  Vector6 V, F_ext;
  V << body.v, body.angular_velocity;
  F_ext << body.force, body.torque;
  return V / dt + M_inverse * F_ext;
}

}  // namespace

Problem make_problem(const std::vector<RigidBody>& bodies, const std::vector<ConstraintRow>& rows,
                     double dt) {
  Problem p;
  std::vector<Vector6> unconstrained;
  for (const RigidBody& body : bodies) {
    p.M_inverse.push_back(inverse_mass_block(body));
    unconstrained.push_back(unconstrained_velocity(body, p.M_inverse.back(), dt));
  }
  for (const ConstraintRow& row : rows) {
    p.Jsp.push_back(row.Jsp);
    p.Jmap.push_back(row.Jmap);
    p.lambda_min.push_back(row.lambda_min);
    p.lambda_max.push_back(row.lambda_max);
    p.friction_of.push_back(row.friction_of);
    p.mu.push_back(row.mu);
  }
  // "Computing Jacobian": J (V/Δt + M⁻¹ F_ext) by Multiply
  const std::vector<double> J_times = Multiply(p.Jsp, p.Jmap, unconstrained);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    // eq. 3-16: η = ζ/Δt − J (V/Δt + M⁻¹ F_ext)
    p.eta.push_back(rows[i].zeta / dt - J_times[i]);
  }
  return p;
}

Blocks Convert(const Blocks& Jsp, const BodyMap& Jmap, const std::vector<Matrix6x6>& M_inverse) {
  Blocks Result(Jsp.size(), {Vector6::Zero(), Vector6::Zero()});
  for (std::size_t i = 0; i < Jsp.size(); ++i) {
    const int b1 = Jmap[i][0];
    const int b2 = Jmap[i][1];
    Result[i][0] = M_inverse[b1] * Jsp[i][0];
    // the text has no b2 = −1 guard here: it reads M⁻¹[−1] for a one-body row, whose second
    // block stays zero
    if (b2 >= 0) Result[i][1] = M_inverse[b2] * Jsp[i][1];
  }
  return Result;
}

std::vector<double> Multiply(const Blocks& Jsp, const BodyMap& Jmap, const std::vector<Vector6>& V) {
  std::vector<double> Result(Jsp.size());
  for (std::size_t i = 0; i < Jsp.size(); ++i) {
    const int b1 = Jmap[i][0];
    const int b2 = Jmap[i][1];
    double Sum = 0.0;
    Sum = Sum + Jsp[i][0].dot(V[b1]);
    if (b2 >= 0) Sum = Sum + Jsp[i][1].dot(V[b2]);
    Result[i] = Sum;
  }
  return Result;
}

std::vector<Vector6> TransposeMultiply(const Blocks& Bsp, const BodyMap& Jmap,
                                       const std::vector<double>& lambda, int n) {
  std::vector<Vector6> Result(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) Result[i] = Vector6::Zero();
  for (std::size_t i = 0; i < Bsp.size(); ++i) {
    const int b1 = Jmap[i][0];
    const int b2 = Jmap[i][1];
    // the text writes λ[b1]; it must be λ[i], row i's multiplier
    Result[b1] = Result[b1] + lambda[i] * Bsp[i][0];
    // the text writes λ[b2]; it must be λ[i]. Nor has it a b2 = −1 guard: it adds to Result[−1]
    if (b2 >= 0) Result[b2] = Result[b2] + lambda[i] * Bsp[i][1];
  }
  return Result;
}

std::vector<double> ProjectedGaussSeidel(const Problem& problem, const std::vector<double>& lambda_exp,
                                         int max_iteration, Trace* trace) {
  const Blocks& Jsp = problem.Jsp;
  const BodyMap& Jmap = problem.Jmap;
  const std::vector<double>& eta = problem.eta;
  const std::size_t s = Jsp.size();
  const int n = static_cast<int>(problem.M_inverse.size());
  std::vector<double> lambda_min = problem.lambda_min;
  std::vector<double> lambda_max = problem.lambda_max;
  // B = M⁻¹Jᵀ, Bᵀ = J M⁻¹
  const Blocks Bsp = Convert(Jsp, Jmap, problem.M_inverse);
  std::vector<double> lambda = lambda_exp;
  // a = B λ
  std::vector<Vector6> a = TransposeMultiply(Bsp, Jmap, lambda, n);
  // d_i = J_i B_i, the diagonal of J B
  std::vector<double> d(s);
  for (std::size_t i = 0; i < s; ++i) d[i] = Jsp[i][0].dot(Bsp[i][0]) + Jsp[i][1].dot(Bsp[i][1]);
  if (trace != nullptr) *trace = Trace{Bsp, d, a, {}, {}};
  for (int Iter = 0; Iter < max_iteration; ++Iter) {
    for (std::size_t i = 0; i < s; ++i) {
      const int b1 = Jmap[i][0];
      const int b2 = Jmap[i][1];
      // Gauss-Seidel's Delta = (B[i] − Σ_j A[i][j] λ[j]) / A[i][i], with A = J B and A λ = J a
      double numerator = eta[i] - Jsp[i][0].dot(a[b1]);
      // the text has no b2 = −1 guard here: it reads Jsp[i][1]·a[−1] for a one-body row
      if (b2 >= 0) numerator = numerator - Jsp[i][1].dot(a[b2]);
      const double Delta = numerator / d[i];
      const double Old = lambda[i];
      // chapter 4, "Friction constraint": λ⁻_i = −μ λc, λ⁺_i = μ λc, λc its contact row's λ now
      if (problem.friction_of[i] >= 0) {
        lambda_min[i] = -problem.mu[i] * lambda[problem.friction_of[i]];
        lambda_max[i] = problem.mu[i] * lambda[problem.friction_of[i]];
      }
      // eq. 3-24: λ⁻ ≤ λ ≤ λ⁺
      lambda[i] = std::max(lambda_min[i], std::min(lambda[i] + Delta, lambda_max[i]));
      const double Diff = lambda[i] - Old;
      a[b1] = a[b1] + Diff * Bsp[i][0];
      // the text has no b2 = −1 guard here: it writes a[−1] for a one-body row
      if (b2 >= 0) a[b2] = a[b2] + Diff * Bsp[i][1];
    }
    if (trace != nullptr) trace->lambda_after_sweep.push_back(lambda);
  }
  if (trace != nullptr) trace->a = a;
  return lambda;
}

}  // namespace lamina::text
