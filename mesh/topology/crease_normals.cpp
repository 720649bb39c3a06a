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

// Two faces closer than this (its cosine) lie in one plane: a planar face's
// triangles, whose corners a file rounds to floats (10^-7 of their size),
// turn from each other by far less; a smooth surface cut finely enough to
// turn by less has no facet to show either way.
constexpr double kCoplanarCos = 0.9999999999847691;  // cos 0.001 degrees

// Per triangle, the area of the flat face it is part of: the triangles
// joined to it across edges (two triangles that share two points) in one
// plane, found by union-find (Tarjan 1975) over the triangles round each
// point (`first` and `round` of crease_normals). Twice the area, as `area`
// (twice each triangle's; 0 for a degenerate one). The planes are compared
// in double, worked out for the few pairs that share an edge.
std::vector<double> flat_face_areas(const std::vector<glm::dvec3>& points, const std::vector<std::array<uint32_t, 3>>& triangles,
                                    const std::vector<double>& area, const std::vector<uint32_t>& first,
                                    const std::vector<uint32_t>& round) {
  const uint32_t count = uint32_t(triangles.size());
  const auto unit = [&](uint32_t t) {
    const auto& [a, b, c] = triangles[t];
    return glm::cross(points[b] - points[a], points[c] - points[a]) / area[t];
  };
  std::vector<uint32_t> parent(count);
  for (uint32_t t = 0; t < count; ++t) parent[t] = t;
  const auto root = [&](uint32_t t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];  // path halving
    return t;
  };
  for (uint32_t t = 0; t < count; ++t) {
    if (area[t] == 0.0) continue;
    for (uint32_t k = 0; k < 3; ++k) {
      const uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      for (uint32_t i = first[a]; i < first[a + 1]; ++i) {
        const uint32_t u = round[i] / 3;
        if (u <= t || area[u] == 0.0) continue;
        if (triangles[u][0] != b && triangles[u][1] != b && triangles[u][2] != b) continue;
        if (glm::dot(unit(t), unit(u)) < kCoplanarCos) continue;
        const uint32_t p = root(t), q = root(u);
        if (p != q) parent[std::max(p, q)] = std::min(p, q);
      }
    }
  }
  std::vector<double> sum(count, 0.0);
  for (uint32_t t = 0; t < count; ++t) sum[root(t)] += area[t];
  std::vector<double> flat(count);
  for (uint32_t t = 0; t < count; ++t) flat[t] = sum[root(t)];
  return flat;
}

}  // namespace

std::vector<std::array<glm::vec3, 3>> crease_normals(const std::vector<glm::dvec3>& points,
                                                     const std::vector<std::array<uint32_t, 3>>& triangles, double crease_deg) {
  const size_t count = triangles.size();
  // Each triangle's unit normal, kept in float: normals are read round every
  // point, and the halved memory is most of what this costs; and twice its
  // area, in double.
  std::vector<glm::vec3> face(count, glm::vec3(0.0f));
  std::vector<double> area(count, 0.0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t < r.end(); ++t) {
      const auto& [a, b, c] = triangles[t];
      const glm::dvec3 n = glm::cross(points[b] - points[a], points[c] - points[a]);
      const double length = glm::length(n);
      if (!(length > 0.0) || !std::isfinite(length)) continue;  // degenerate: no normal, no weight
      face[t] = glm::vec3(n / length);
      area[t] = length;
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
  const std::vector<double> flat_area = flat_face_areas(points, triangles, area, first, round);
  double mean = 0.0;
  for (const double a : area) mean += a / double(count);
  // Each triangle's weight at each corner: its angle there times its flat
  // face's area over the triangles' mean area (a ratio, which a float holds
  // for any scale of coordinates).
  std::vector<std::array<float, 3>> angle(count, {0.0f, 0.0f, 0.0f});
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t < r.end(); ++t) {
      if (area[t] == 0.0) continue;
      const double scale = flat_area[t] / mean;
      for (int k = 0; k < 3; ++k)
        angle[t][size_t(k)] = float(scale * corner_angle(points[triangles[t][size_t(k)]], points[triangles[t][size_t((k + 1) % 3)]],
                                                   points[triangles[t][size_t((k + 2) % 3)]]));
    }
  });

  const double min_cos = std::cos(glm::radians(crease_deg));
  // Within half the crease angle of the point's mean normal, every two
  // faces are within the crease angle of each other: then every corner at
  // the point takes that mean, and the point costs its faces once, not
  // their square (the common case: a scan is smooth all over).
  const double half_cos = std::cos(glm::radians(crease_deg / 2.0));
  std::vector<std::array<glm::vec3, 3>> normals(count);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v < r.end(); ++v) {
      glm::dvec3 all(0.0);
      for (uint32_t i = first[v]; i < first[v + 1]; ++i) all += double(angle[round[i] / 3][round[i] % 3]) * glm::dvec3(face[round[i] / 3]);
      const double all_length = glm::length(all);
      bool one_mean = all_length > 0.0;
      for (uint32_t i = first[v]; i < first[v + 1] && one_mean; ++i) {
        const glm::dvec3 f(face[round[i] / 3]);
        one_mean = f == glm::dvec3(0.0) || glm::dot(f, all) >= half_cos * all_length;
      }
      for (uint32_t i = first[v]; i < first[v + 1]; ++i) {
        const uint32_t t = round[i] / 3, k = round[i] % 3;
        if (face[t] == glm::vec3(0.0f)) {
          normals[t][k] = glm::vec3(0.0f);
          continue;
        }
        if (one_mean) {
          normals[t][k] = glm::vec3(all / all_length);
          continue;
        }
        glm::dvec3 sum(0.0);
        for (uint32_t j = first[v]; j < first[v + 1]; ++j) {
          const uint32_t u = round[j] / 3;
          if (glm::dot(glm::dvec3(face[t]), glm::dvec3(face[u])) >= min_cos) sum += double(angle[u][round[j] % 3]) * glm::dvec3(face[u]);
        }
        const double length = glm::length(sum);
        normals[t][k] = length > 0.0 ? glm::vec3(sum / length) : face[t];
      }
    }
  });
  return normals;
}

}  // namespace umbra
