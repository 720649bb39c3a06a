#include "scene/terminator.hpp"

#include <algorithm>
#include <atomic>
#include <utility>

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

std::vector<uint8_t> terminator_triangles(const Mesh& mesh, const std::vector<int8_t>& sides) {
  const size_t count = mesh.triangles.size();
  std::vector<uint8_t> on_terminator(count, 0);
  // The points round which the triangles have the light both strictly in
  // front and not, marked on every core (racing marks all write 1).
  std::vector<std::atomic<uint8_t>> in_front(mesh.positions.size()), not_in_front(mesh.positions.size());
  // The corners at those points, (point, 3 t + k), each block's in
  // triangle order: a few per point of the terminator, a curve.
  constexpr size_t kBlock = 16384;
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> found((count + kBlock - 1) / kBlock);
  // Isolated, as triangle_light_sides is.
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, kBlock), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t t = r.begin(); t < r.end(); ++t)
        for (const uint32_t v : mesh.triangles[t]) (sides[t] > 0 ? in_front : not_in_front)[v].store(1, std::memory_order_relaxed);
    });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, found.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t b = r.begin(); b < r.end(); ++b)
        for (size_t t = b * kBlock; t < std::min(count, (b + 1) * kBlock); ++t)
          for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            if (in_front[v].load(std::memory_order_relaxed) && not_in_front[v].load(std::memory_order_relaxed))
              found[b].push_back({v, uint32_t(3 * t + k)});
          }
    });
  });
  std::vector<std::pair<uint32_t, uint32_t>> corners;
  for (const auto& block : found) corners.insert(corners.end(), block.begin(), block.end());
  std::sort(corners.begin(), corners.end());  // by point: each point's corners in a run
  const float kSameShading = 0.98480775f;  // cos 10 degrees
  for (size_t first = 0; first < corners.size();) {
    size_t end = first;
    while (end < corners.size() && corners[end].first == corners[first].first) ++end;
    for (size_t i = first; i < end; ++i)
      for (size_t j = first; j < end && !on_terminator[corners[i].second / 3]; ++j) {
        const uint32_t c = corners[i].second, d = corners[j].second;
        const uint32_t t = c / 3, u = d / 3;
        if ((sides[t] > 0) == (sides[u] > 0)) continue;
        if (glm::dot(mesh.triangle_normals[t][c % 3], mesh.triangle_normals[u][d % 3]) < kSameShading) continue;
        on_terminator[t] = 1;
      }
    first = end;
  }
  return on_terminator;
}

}  // namespace umbra
