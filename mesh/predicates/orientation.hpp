#pragma once
// Exact geometric predicates on double coordinates (CGAL's filtered exact
// predicates): the answer is the sign of the exact determinant, so two
// callers asking the same question never disagree, however close to zero.

#include <glm/vec3.hpp>

namespace umbra {

// Sign of the triple product (b - a) x (c - a) . (d - a): +1 when d lies on the
// side of plane abc that the normal (b - a) x (c - a) points to, -1 on the
// other side, 0 when the four points are coplanar.
int orientation(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

// True when a, b and c lie on one line (including repeated points).
bool collinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// True when p lies on the closed triangle abc (its plane, inside or on an edge).
bool on_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& p);

// Sign of |p - center|^2 - radius^2, exactly: -1 inside the sphere, 0 on it,
// +1 outside.
int side_of_sphere(const glm::dvec3& center, double radius, const glm::dvec3& p);

}  // namespace umbra
