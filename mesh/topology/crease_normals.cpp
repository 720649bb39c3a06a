#include "mesh/topology/crease_normals.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace umbra {
namespace {

// The angle at corner k of a triangle, between its two edges there.
double corner_angle(const glm::dvec3& at, const glm::dvec3& next, const glm::dvec3& previous) {
  const glm::dvec3 a = next - at, b = previous - at;
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

std::vector<std::array<glm::vec3, 3>> crease_normals(const std::vector<glm::dvec3>& points,
                                                     const std::vector<std::array<uint32_t, 3>>& triangles, double crease_deg) {
  const size_t count = triangles.size();
  std::vector<glm::dvec3> face(count, glm::dvec3(0.0));
  std::vector<std::array<double, 3>> angle(count, {0.0, 0.0, 0.0});
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t < r.end(); ++t) {
      const auto& [a, b, c] = triangles[t];
      const glm::dvec3 n = glm::cross(points[b] - points[a], points[c] - points[a]);
      const double length = glm::length(n);
      if (!(length > 0.0) || !std::isfinite(length)) continue;  // degenerate: no normal, no weight
      face[t] = n / length;
      for (int k = 0; k < 3; ++k)
        angle[t][size_t(k)] = corner_angle(points[triangles[t][size_t(k)]], points[triangles[t][size_t((k + 1) % 3)]],
                                           points[triangles[t][size_t((k + 2) % 3)]]);
    }
  });
  // The triangles round each point, as (triangle, corner) pairs in one array.
  std::vector<uint32_t> first(points.size() + 1, 0);
  for (const auto& t : triangles)
    for (const uint32_t v : t) ++first[v + 1];
  for (size_t v = 0; v < points.size(); ++v) first[v + 1] += first[v];
  std::vector<uint32_t> round(first.back());
  std::vector<uint32_t> filled(first.begin(), first.end() - 1);
  for (uint32_t t = 0; t < count; ++t)
    for (uint32_t k = 0; k < 3; ++k) round[filled[triangles[t][k]]++] = 3 * t + k;

  const double min_cos = std::cos(glm::radians(crease_deg));
  std::vector<std::array<glm::vec3, 3>> normals(count);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t < r.end(); ++t) {
      for (size_t k = 0; k < 3; ++k) {
        if (face[t] == glm::dvec3(0.0)) {
          normals[t][k] = glm::vec3(0.0f);
          continue;
        }
        const uint32_t v = triangles[t][k];
        glm::dvec3 sum(0.0);
        for (uint32_t i = first[v]; i < first[v + 1]; ++i) {
          const uint32_t u = round[i] / 3, j = round[i] % 3;
          if (glm::dot(face[t], face[u]) >= min_cos) sum += angle[u][j] * face[u];
        }
        const double length = glm::length(sum);
        normals[t][k] = glm::vec3(length > 0.0 ? sum / length : face[t]);
      }
    }
  });
  return normals;
}

}  // namespace umbra
