#include "scene/terminator.hpp"

#include <unordered_map>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "mesh/predicates/orientation.hpp"

namespace umbra {

std::vector<int8_t> triangle_light_sides(const Mesh& mesh, const glm::dvec3& light) {
  std::vector<int8_t> sides(mesh.triangles.size());
  const std::vector<glm::dvec3>& p = mesh.positions;
  // Isolated: while it waits for its share, this thread takes none of the
  // other work under way (umbra render makes the plan meanwhile).
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, sides.size(), 16384), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i < r.end(); ++i) {
        const auto& t = mesh.triangles[i];
        sides[i] = int8_t(orientation(p[t[0]], p[t[1]], p[t[2]], light));
      }
    });
  });
  return sides;
}

std::vector<std::array<uint8_t, 3>> terminator_corners(const Mesh& mesh, const std::vector<int8_t>& sides) {
  std::vector<std::array<uint8_t, 3>> fade(mesh.triangles.size(), {0, 0, 0});
  // The points whose triangles have the light on more than one side (bit 0:
  // in front, bit 1: behind or in the plane), and the corners at them.
  std::vector<uint8_t> seen(mesh.positions.size(), 0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const uint32_t v : mesh.triangles[t]) seen[v] |= sides[t] > 0 ? 1 : 2;
  std::unordered_map<uint32_t, std::vector<uint32_t>> corners_at;  // point: 3 t + k
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (uint32_t k = 0; k < 3; ++k)
      if (seen[mesh.triangles[t][k]] == 3) corners_at[mesh.triangles[t][k]].push_back(3 * t + k);
  const float kSameShading = 0.98480775f;  // cos 10 degrees
  for (const auto& [point, corners] : corners_at)
    for (const uint32_t c : corners)
      for (const uint32_t d : corners) {
        const uint32_t t = c / 3, u = d / 3;
        if ((sides[t] > 0) == (sides[u] > 0)) continue;
        if (glm::dot(mesh.triangle_normals[t][c % 3], mesh.triangle_normals[u][d % 3]) < kSameShading) continue;
        fade[t][c % 3] = 1;
        break;
      }
  return fade;
}

}  // namespace umbra
