#pragma once
// The exact ray tests of the CPU reference, in double precision, shared by
// the brute-force search (ray_cast.cpp) and the Embree one (ray_caster.cpp),
// so that both give the same hit bit for bit.

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

// Both roots of |o + t d - c|^2 = R^2 for unit d, in the stable form.
inline std::optional<double> hit_sphere(const Sphere& s, const glm::dvec3& o, const glm::dvec3& d, double t_min) {
  const glm::dvec3 oc = o - s.center;
  const double b = glm::dot(oc, d);
  const glm::dvec3 closest = oc - b * d;
  const double h = s.radius * s.radius - glm::dot(closest, closest);
  if (h < 0.0) return std::nullopt;
  const double root = std::sqrt(h);
  if (-b - root > t_min) return -b - root;
  if (-b + root > t_min) return -b + root;
  return std::nullopt;
}

// Moller-Trumbore, accepting either side; the edges are inclusive.
inline std::optional<double> hit_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& o,
                                   const glm::dvec3& d, double t_min) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0) return std::nullopt;  // parallel to the plane, or degenerate
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(e2, q) / det;
  if (t > t_min) return t;
  return std::nullopt;
}

}  // namespace umbra
