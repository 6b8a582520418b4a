// The Eigen types every stage uses, named as the text names them.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lamina {

using Vec3 = Eigen::Vector3d;            // a vector in R³ (position, velocity, force, ...)
using Mat3 = Eigen::Matrix3d;            // a 3×3 matrix (rotation R, inertia tensor I)
using Quat = Eigen::Quaterniond;         // a quaternion w + (x, y, z); unit when it is an orientation
using Vec6 = Eigen::Matrix<double, 6, 1>;  // one body's block of V or of a Jacobian row: [v; ω]
using Vec2 = Eigen::Vector2d;            // a vector in the x–y plane of Lamina's scenes (m, or pixels)
using Mat2 = Eigen::Matrix2d;            // a rotation in the plane

// E, the 3×3 identity of the text.
inline Mat3 identity3() { return Mat3::Identity(); }

}  // namespace lamina
