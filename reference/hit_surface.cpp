#include "reference/hit_surface.hpp"

#include <glm/geometric.hpp>

namespace umbra {

Surface surface_of(const Scene& scene, int object) {
  const size_t o = size_t(object);
  if (o < scene.spheres.size()) return {scene.spheres[o].material};
  size_t first = scene.spheres.size();
  if (o < first + scene.triangles.size()) return {scene.triangles[o - first].material};
  first += scene.triangles.size();
  for (const Mesh& m : scene.meshes) {
    if (o < first + m.triangles.size()) return {m.material_of(o - first), &m, o - first};
    first += m.triangles.size();
  }
  return {};
}

CornerBlend::CornerBlend(const Surface& s, const glm::dvec3& p) {
  const auto& t = s.mesh->triangles[s.triangle];
  const glm::dvec3 a = s.mesh->positions[t[0]], b = s.mesh->positions[t[1]], c = s.mesh->positions[t[2]];
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double area = glm::dot(n, n);
  wb = area > 0.0 ? glm::dot(glm::cross(p - a, c - a), n) / area : 0.0;
  wc = area > 0.0 ? glm::dot(glm::cross(b - a, p - a), n) / area : 0.0;
  wa = 1.0 - wb - wc;
}

std::optional<glm::dvec3> shading_normal(const Surface& s, const glm::dvec3& p) {
  if (!s.mesh || s.mesh->triangle_normals.empty()) return std::nullopt;
  const auto& corners = s.mesh->triangle_normals[s.triangle];
  if (corners[0] == glm::vec3(0.0f)) return std::nullopt;  // a flat face's corners are all 0
  return glm::normalize(CornerBlend(s, p)(corners));
}

}  // namespace umbra
