#include "mesh/orientation.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

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

}  // namespace umbra
