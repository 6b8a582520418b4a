// One row of the constraint Jacobian in the text's sparse form ("Computing Jacobian").
//
// Glossary (chapter 3):
//   J      the s × 6n Jacobian; row i touches at most two bodies (eq. 3-8)
//   Jsp    the row's two non-zero 1 × 6 blocks, one per body, each laid out as [v ω]
//   Jmap   the two body indices of those blocks; Jmap[1] = −1 for a one-body row
//   ζ      the bias of the row's velocity constraint J V(t+Δt) = ζ (eq. 3-15)
//   λ⁻, λ⁺ the bounds of the row's multiplier (eq. 3-24..3-26)
#pragma once

#include <array>
#include <limits>

#include "kinematics/math_types.h"

namespace lamina {

inline constexpr double infinity = std::numeric_limits<double>::infinity();

struct ConstraintRow {
  std::array<Vec6, 2> Jsp{Vec6::Zero(), Vec6::Zero()};  // the row's blocks for Jmap[0], Jmap[1]
  std::array<int, 2> Jmap{-1, -1};  // body indices; −1 for none (a one-body row)
  double zeta = 0.0;                // ζ, the velocity the row asks for, in m/s or rad/s (eq. 3-15)
  double lambda_min = -infinity;    // λ⁻, lower bound of λ, in N (eq. 3-24)
  double lambda_max = infinity;     // λ⁺, upper bound of λ, in N (eq. 3-24)
  // A friction row's bounds are ±μ λc, read from its contact row's current λ during the
  // iterations (eq. 3-26 and chapter 4, "friction"); −1 for a row with fixed bounds. A row for a
  // whole two-point manifold is bounded by ±μ (λc1 + λc2), its contact rows' sum.
  int friction_of = -1;             // index of the (first) contact row bounding this one, or −1
  int friction_count = 1;           // how many consecutive contact rows from friction_of bound it
  double mu = 0.0;                  // μ of a friction row

  bool is_one_body() const { return Jmap[1] < 0; }
};

// Where a contact pair's or a joint's rows sit among a step's rows: first .. first + count − 1.
// Recorded when the rows are written and read back from there (the row map), never re-derived.
struct RowRange {
  int first = 0;  // the index of the first row
  int count = 0;  // how many rows
};

}  // namespace lamina
