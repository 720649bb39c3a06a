#include "render/planar_receivers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "mesh/predicates/orientation.hpp"
#include "render/caster_entries.hpp"
#include "silhouette/sphere_volume.hpp"

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

// Planar projection: which planes receive, and what is projected onto them.
void plan_planar_light(const Scene& scene, const std::vector<ReceiverPlane>& receivers, int segments, const Light& light,
                       LightPlan& lp) {
  clear_volumes(lp);
  lp.mesh_volumes.clear();
  lp.count = DepthCount::kWhereDepthFails;  // nothing is counted: the volumes' defaults
  lp.culled_casters = 0;
  std::string lines;
  int planes = 0;
  for (const ReceiverPlane& r : receivers) {
    const Triangle& t = scene.triangles[r.first_triangle];
    if (orientation(t.a, t.b, t.c, light.position) == 0) continue;  // the light in the plane (exactly): no shadow on it
    const double height = glm::dot(r.plane, glm::dvec4(light.position, 1.0));
    lp.planar.receiver_planes.push_back(height > 0.0 ? r.plane : -r.plane);
    ++planes;
    for (const int line : r.lines) lines += (lines.empty() ? "" : ", ") + std::to_string(line);
  }
  lp.count_reason = "no volume count: every caster projected onto " + std::to_string(planes) +
                    " receiver plane(s) (triangles at lines " + (lines.empty() ? std::string("none") : lines) +
                    "); spheres and meshes receive no shadow";
  const auto add = [&](const char* kind, const FileLoc& where, const std::string& method, const ShadowVolume& v) {
    lp.casters.push_back({kind, where, "projected (Blinn 1988): " + method, {}});
    ShadowVolume finite;  // the triangles whose vertices are all finite (the light cap), and only their vertices
    std::vector<uint32_t> index(v.vertices.size(), UINT32_MAX);
    for (size_t k = 0; k < v.vertices.size(); ++k)
      if (v.vertices[k].w == 1.0) index[k] = uint32_t(finite.vertices.size()), finite.vertices.push_back(v.vertices[k]);
    for (const auto& t : v.triangles)
      if (index[t[0]] != UINT32_MAX && index[t[1]] != UINT32_MAX && index[t[2]] != UINT32_MAX)
        finite.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    append_volume(lp.planar.casters, finite);
  };
  for (const Sphere& s : scene.spheres)
    add("sphere", s.where, "its tangent " + std::to_string(segments) + "-gon disc",
        sphere_volume(s.center, s.radius, light.position, segments));
  for (const Triangle& t : scene.triangles) {
    ShadowVolume v;
    v.vertices = {glm::dvec4(t.a, 1.0), glm::dvec4(t.b, 1.0), glm::dvec4(t.c, 1.0)};
    v.triangles = {{0, 1, 2}};
    add("triangle", t.where, "the triangle", v);
  }
  for (const Mesh& m : scene.meshes) {
    ShadowVolume v;
    for (const glm::dvec3& p : m.positions) v.vertices.emplace_back(p, 1.0);
    v.triangles = m.triangles;
    add("mesh", m.where, "its " + std::to_string(m.triangles.size()) + " triangles", v);
  }
  std::stable_sort(lp.casters.begin(), lp.casters.end(),
                   [](const CasterEntry& a, const CasterEntry& b) { return a.where.line < b.where.line; });
}

}  // namespace umbra
