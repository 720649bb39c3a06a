#include "mesh/predicates/orientation.hpp"

#include <algorithm>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

namespace umbra {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
Kernel::Point_3 point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }
}  // namespace

int orientation(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  // CGAL's sign is that of det[b - a, c - a, d - a], the same convention.
  return int(CGAL::orientation(point(a), point(b), point(c), point(d)));
}

bool collinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return CGAL::collinear(point(a), point(b), point(c));
}

bool on_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& p) {
  // Outside the triangle's box (compared exactly, as doubles) it cannot be on
  // it: the exact predicates are left for the few triangles whose box holds p.
  for (int k = 0; k < 3; ++k)
    if (p[k] < std::min({a[k], b[k], c[k]}) || p[k] > std::max({a[k], b[k], c[k]})) return false;
  if (CGAL::orientation(point(a), point(b), point(c), point(p)) != CGAL::COPLANAR) return false;
  if (CGAL::collinear(point(a), point(b), point(c)))  // degenerate: on one of its segments
    return CGAL::Segment_3<Kernel>(point(a), point(b)).has_on(point(p)) ||
           CGAL::Segment_3<Kernel>(point(b), point(c)).has_on(point(p)) ||
           CGAL::Segment_3<Kernel>(point(a), point(c)).has_on(point(p));
  return CGAL::Triangle_3<Kernel>(point(a), point(b), point(c)).has_on(point(p));
}

int side_of_sphere(const glm::dvec3& center, double radius, const glm::dvec3& p) {
  // Rationals hold every double and their products exactly; a scene has few
  // spheres and lights, so the exact path is cheap enough to take always.
  using Q = CGAL::Exact_rational;
  Q sum = -Q(radius) * Q(radius);
  for (int i = 0; i < 3; ++i) {
    const Q d = Q(p[i]) - Q(center[i]);
    sum += d * d;
  }
  return CGAL::sign(sum);
}

}  // namespace umbra
