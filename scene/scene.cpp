#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace umbra {

Camera spec_camera() {
  // tan(45deg / 2) * (3.4 - 1) = 0.994: the face z = 1 spans 99.4% of the height.
  return Camera{{0.0, 0.0, 3.4}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 45.0};
}

SceneBounds surface_bounds(const Scene& scene) {
  SceneBounds b;
  for (const Sphere& s : scene.spheres) b.grow(surface_bounds(s));
  for (const Triangle& t : scene.triangles) b.grow(surface_bounds(t));
  for (const Mesh& m : scene.meshes) b.grow(surface_bounds(m));
  return b;
}

SceneBounds surface_bounds(const Sphere& s) { return {s.center - s.radius, s.center + s.radius}; }

SceneBounds surface_bounds(const Triangle& t) {
  return {glm::min(t.a, glm::min(t.b, t.c)), glm::max(t.a, glm::max(t.b, t.c))};
}

SceneBounds surface_bounds(const Mesh& m) { return m.triangles.empty() ? SceneBounds{} : SceneBounds{m.bounds_min, m.bounds_max}; }

namespace {

// The distance from p to triangle abc: the closest point found by the
// triangle's Voronoi regions (Ericson, "Real-Time Collision Detection", 2005, 5.1.5).
double distance_to_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return glm::length(ap);
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return glm::length(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::length(p - (a + d1 / (d1 - d3) * ab));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return glm::length(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::length(p - (a + d2 / (d2 - d6) * ac));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return glm::length(p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b)));
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) return std::min({glm::length(ap), glm::length(bp), glm::length(cp)});  // collinear corners
  return glm::length(p - (a + (vb / denominator) * ab + (vc / denominator) * ac));
}

double distance_to_box(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
  return glm::length(glm::max(glm::dvec3(0.0), glm::max(lo - p, p - hi)));
}

}  // namespace

double nearest_surface_distance(const Scene& scene, const glm::dvec3& point) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Sphere& s : scene.spheres) nearest = std::min(nearest, std::abs(glm::length(point - s.center) - s.radius));
  for (const Triangle& t : scene.triangles) nearest = std::min(nearest, distance_to_triangle(point, t.a, t.b, t.c));
  for (const Mesh& m : scene.meshes) {
    if (m.triangles.empty()) continue;
    const double to_box = distance_to_box(point, m.bounds_min, m.bounds_max);
    if (to_box > 0.0 || nearest == 0.0) {
      nearest = std::min(nearest, to_box);
      continue;
    }
    // Inside the mesh's box (a viewer zoomed in): every triangle, on every core.
    nearest = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, m.triangles.size(), 16384), nearest,
        [&](const tbb::blocked_range<size_t>& r, double least) {
          for (size_t k = r.begin(); k < r.end(); ++k) {
            const auto& t = m.triangles[k];
            least = std::min(least, distance_to_triangle(point, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
          }
          return least;
        },
        [](double a, double b) { return std::min(a, b); });
  }
  return nearest;
}

void rotate_lights_about_z(Scene& scene, double degrees) {
  for (Light& light : scene.lights) light.position = rotated_about_z(light.position, degrees);
}

glm::dvec3 rotated_about_z(const glm::dvec3& p, double degrees) {
  const double a = degrees * M_PI / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  return {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
}

}  // namespace umbra
