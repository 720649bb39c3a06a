#pragma once
// A projection of space onto a coordinate plane with an exact orientation
// test, for the self-intersection search: dropping a coordinate is exact, and
// on any plane not parallel to the dropped axis it is an affine bijection, so
// orientations there keep or all reverse their signs.

#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace umbra {

struct CoordinateProjection {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;

  int u, v;  // the kept axes; (u, v, dropped) is a cyclic order of (x, y, z)

  // Drops the axis along which `normal` is largest.
  explicit CoordinateProjection(const Kernel::Vector_3& normal) {
    const double ax = std::abs(normal.x()), ay = std::abs(normal.y()), az = std::abs(normal.z());
    const int drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    u = (drop + 1) % 3, v = (drop + 2) % 3;
  }
  // Drops the axis along which the normal of triangle pqr is largest, so that
  // the triangle's projection has area.
  CoordinateProjection(const Point& p, const Point& q, const Point& r)
      : CoordinateProjection(CGAL::cross_product(q - p, r - p)) {}

  // The exact orientation of the projected points: the determinant in
  // doubles when it exceeds Shewchuk's bound on its rounding error
  // ("Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
  // Predicates", 1997: ccwerrboundA = (3 + 16 eps) eps), else CGAL's exact
  // predicate.
  CGAL::Orientation orientation(const Point& p, const Point& q, const Point& r) const {
    const double left = (p[u] - r[u]) * (q[v] - r[v]), right = (p[v] - r[v]) * (q[u] - r[u]);
    const double det = left - right;
    constexpr double kEpsilon = 0x1p-53;
    constexpr double kBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
    if (std::abs(det) > kBound * (std::abs(left) + std::abs(right))) return det > 0 ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
    return CGAL::orientation(Kernel::Point_2(p[u], p[v]), Kernel::Point_2(q[u], q[v]), Kernel::Point_2(r[u], r[v]));
  }
};

}  // namespace umbra
