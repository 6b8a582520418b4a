#include "kinematics/mass_properties.h"

#include <cassert>
#include <cmath>

#include "kinematics/inertia.h"

namespace lamina {

AreaMoments polygon_moments(const std::vector<Vec2>& vertices) {
  assert(vertices.size() >= 3);
  // The fan's apex o is the first vertex, so the sums stay small for a polygon far from the origin.
  const Vec2 o = vertices[0];
  double area = 0.0;
  Vec2 first = Vec2::Zero();    // ∫ r dA, r from o
  Mat2 second = Mat2::Zero();   // ∫ r rᵀ dA, r from o
  for (std::size_t i = 1; i + 1 < vertices.size(); ++i) {
    const Vec2 p = vertices[i] - o;
    const Vec2 q = vertices[i + 1] - o;
    const double a = 0.5 * (p.x() * q.y() - p.y() * q.x());  // the triangle's signed area
    area += a;
    first += a * (p + q) / 3.0;
    const double xx = a * (p.x() * p.x() + p.x() * q.x() + q.x() * q.x()) / 6.0;
    const double yy = a * (p.y() * p.y() + p.y() * q.y() + q.y() * q.y()) / 6.0;
    const double xy =
        a * (2.0 * p.x() * p.y() + p.x() * q.y() + q.x() * p.y() + 2.0 * q.x() * q.y()) / 12.0;
    second += (Mat2() << xx, xy, xy, yy).finished();
  }
  AreaMoments m;
  m.area = area;
  const Vec2 c = first / area;  // the centroid, from o
  m.centroid = o + c;
  // Parallel axis theorem: J about c = ∫ r rᵀ dA − A c cᵀ.
  m.second = second - area * c * c.transpose();
  return m;
}

AreaMoments capsule_moments(double radius, double length) {
  const double r = radius, l = length;
  const double r2 = r * r;
  AreaMoments m;
  m.area = 2.0 * r * l + M_PI * r2;
  const double xx = r * l * l * l / 6.0 + M_PI * r2 * l * l / 4.0 + 4.0 * r2 * r * l / 3.0 +
                    M_PI * r2 * r2 / 4.0;
  const double yy = 2.0 * r2 * r * l / 3.0 + M_PI * r2 * r2 / 4.0;
  m.second = Vec2(xx, yy).asDiagonal();
  return m;
}

Mat3 prism_inertia(double mass, const AreaMoments& moments) {
  const Mat2& J = moments.second;
  const double per_area = mass / moments.area;
  const double depth = moments.area * planar_depth * planar_depth / 12.0;  // A L²/12
  Mat3 I;
  I << J(1, 1) + depth, -J(0, 1), 0.0,
       -J(0, 1), J(0, 0) + depth, 0.0,
       0.0, 0.0, J(0, 0) + J(1, 1);
  return per_area * I;
}

}  // namespace lamina
