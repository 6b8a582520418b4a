// What is read from an assembled MLCP (mlcp.h)'s packed rows: the text's form of it (Jsp, Bsp,
// Jmap, ζ, η, d, the bounds), W = J B λ − η and its residual, J_i X, and F_c = Jᵀ λ.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "constraints/mlcp.h"

namespace lamina {
namespace {

template <int N>
const PackedRow<N>& row_at(const PackedRows<N>& rows, int i) {
  assert(i >= 0 && i < static_cast<int>(rows.size()));
  return rows[static_cast<std::size_t>(i)];
}

}  // namespace

int Mlcp::row_count() const {
  return visit([](const auto& rows) { return static_cast<int>(rows.size()); });
}

ConstraintRow Mlcp::row(int i) const {
  return visit([&](const auto& rows) {
    const auto& packed = row_at(rows, i);
    ConstraintRow row;
    row.Jmap = packed.map;
    for (int k = 0; k < 2; ++k) row.Jsp[k] = widen(packed.J[k]);
    copy_row_scalars(packed, row);
    return row;
  });
}

std::array<int, 2> Mlcp::bodies_of(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).map; });
}

Vec6 Mlcp::jacobian(int i, int k) const {
  return visit([&](const auto& rows) { return widen(row_at(rows, i).J[k]); });
}

Vec6 Mlcp::b_block(int i, int k) const {
  return visit([&](const auto& rows) { return widen(row_at(rows, i).B[k]); });
}

double Mlcp::zeta(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).zeta; });
}

double Mlcp::eta(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).eta; });
}

double Mlcp::d(int i) const {
  // d_i = J_i · B_i, as assembled
  return visit([&](const auto& rows) {
    const auto& row = row_at(rows, i);
    return row_dot(row.J, row.B[0], row.B[1], true);
  });
}

int Mlcp::friction_of(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).friction_of; });
}

int Mlcp::friction_count(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).friction_count; });
}

double Mlcp::mu(int i) const {
  return visit([&](const auto& rows) { return row_at(rows, i).mu; });
}

std::array<double, 2> Mlcp::bounds(int i, const double* lambda) const {
  return visit([&](const auto& rows) { return bounds_of(row_at(rows, i), lambda); });
}

Eigen::VectorXd Mlcp::slack(const double* lambda) const {
  return visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    std::vector<Block<N>> a;
    transpose_multiply(rows, body_count_, lambda, a);
    Eigen::VectorXd w(static_cast<Eigen::Index>(rows.size()));
    // eq. 3-23: W = J B λ − η
    for (size_t i = 0; i < rows.size(); ++i) {
      w[static_cast<Eigen::Index>(i)] = row_dot(rows[i], a) - rows[i].eta;
    }
    return w;
  });
}

double Mlcp::residual(const double* lambda) const {
  const Eigen::VectorXd w = slack(lambda);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    const auto [lo, hi] = bounds(static_cast<int>(i), lambda);
    // eq. 3-24: W = 0 inside the bounds, W ≥ 0 at λ⁻, W ≤ 0 at λ⁺
    double violation = w[i];
    if (lambda[i] <= lo) violation = std::min(w[i], 0.0);
    if (lambda[i] >= hi) violation = std::max(w[i], 0.0);
    if (lo == hi) violation = 0.0;
    sum += violation * violation;
  }
  return std::sqrt(sum);
}

double Mlcp::row_times(int i, const std::vector<Vec6>& per_body) const {
  return visit([&](const auto& rows) {
    constexpr int N = std::decay_t<decltype(rows)>::value_type::size;
    const auto& row = row_at(rows, i);
    const Block<N> x0 = cut<N>(per_body[row.map[0]]);
    return row_dot<N>(row.J, x0, row.two_bodies() ? cut<N>(per_body[row.map[1]]) : x0,
                      row.two_bodies());
  });
}

void Mlcp::add_constraint_forces(std::vector<RigidBody>& bodies, const double* lambda,
                                 Workers* workers) const {
  const int runs = runs_on(workers);
  // Each thread adds to the bodies of its two runs only (the shares it integrates), taking the
  // groups that touch them in row order: every body's sum in the one-thread order. One walk of
  // the groups a thread, not one a run. On one thread, all the bodies.
  const auto add_own = [&](int t) {
    const std::array<int, 2> own_runs = runs_of_thread(t, runs);
    const std::array<std::pair<std::size_t, std::size_t>, 2> shares{
        share_of(bodies.size(), own_runs[0], runs), share_of(bodies.size(), own_runs[1], runs)};
    const auto own = [&](int body) {
      const auto at = static_cast<std::size_t>(body);
      return runs == 1 || (body >= 0 && ((at >= shares[0].first && at < shares[0].second) ||
                                         (at >= shares[1].first && at < shares[1].second)));
    };
    visit([&](const auto& rows) {
      for (std::size_t g = 0; g + 1 < groups_.size(); ++g) {
        const std::array<bool, 2> to{own(groups_[g].bodies[0]), own(groups_[g].bodies[1])};
        if (!to[0] && !to[1]) continue;
        // eq. 3-11: F_c = Jᵀ λ, this thread's blocks of it
        add_group_forces(rows.data(), lambda, groups_[g].first, groups_[g + 1].first,
                         bodies.data(), to);
      }
    });
  };
  if (runs == 1) {
    add_own(0);
  } else {
    workers->run(add_own);
  }
}

Vec6 Mlcp::constraint_wrench(int body, const double* lambda) const {
  Vec6 wrench = Vec6::Zero();
  visit([&](const auto& rows) {
    // eq. 3-11, 5-9: body b's block of F_c = Jᵀ λ, the terms of its rows in row order
    using Row = typename std::decay_t<decltype(rows)>::value_type;
    for (int i = 0; i < row_count(); ++i) {
      const Row& row = rows[static_cast<std::size_t>(i)];
      if (row.map[0] != body && row.map[1] != body) continue;
      Block<Row::size> f1 = Block<Row::size>::Zero();
      Block<Row::size> f2 = Block<Row::size>::Zero();
      add_force_term(row, lambda[i], f1, f2);
      wrench += widen(row.map[0] == body ? f1 : f2);
    }
  });
  return wrench;
}

}  // namespace lamina
