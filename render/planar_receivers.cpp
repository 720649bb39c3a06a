#include "render/planar_receivers.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "mesh/predicates/orientation.hpp"

namespace umbra {
namespace {

bool same_plane(const glm::dvec4& a, const glm::dvec4& b, double scale) {
  return glm::length(glm::dvec3(a) - glm::dvec3(b)) < 1e-9 && std::abs(a.w - b.w) < 1e-9 * scale;
}

double largest_coordinate(const glm::dvec3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }

}  // namespace

std::vector<ReceiverPlane> receiver_planes(const Scene& scene) {
  std::vector<ReceiverPlane> planes;
  for (size_t i = 0; i < scene.triangles.size(); ++i) {
    const Triangle& t = scene.triangles[i];
    if (collinear(t.a, t.b, t.c)) continue;
    glm::dvec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
    // One orientation per plane: the first non-zero component positive.
    const double first = std::abs(n.x) > 1e-12 ? n.x : std::abs(n.y) > 1e-12 ? n.y : n.z;
    if (first < 0.0) n = -n;
    const glm::dvec4 plane(n, -glm::dot(n, (t.a + t.b + t.c) / 3.0));
    const double scale = largest_coordinate(t.a) + largest_coordinate(t.b) + largest_coordinate(t.c);
    bool merged = false;
    for (ReceiverPlane& r : planes)
      if (same_plane(r.plane, plane, scale)) {
        r.lines.push_back(t.where.line);
        merged = true;
        break;
      }
    if (!merged) planes.push_back({plane, {t.where.line}, i});
  }
  return planes;
}

glm::dmat4 planar_shadow_matrix(const glm::dvec4& plane, const glm::dvec3& light) {
  const glm::dvec4 l(light, 1.0);
  return glm::dot(plane, l) * glm::dmat4(1.0) - glm::outerProduct(l, plane);
}

}  // namespace umbra
