#include "mesh/check/repair_attributes.hpp"

#include <cstring>
#include <limits>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

namespace umbra {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// Hashes a point's coordinates bit for bit, with -0 taken as 0 so that
// points equal by == hash alike.
struct PositionHash {
  size_t operator()(const glm::dvec3& p) const {
    uint64_t h = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const double x = p[axis] == 0.0 ? 0.0 : p[axis];
      uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
      h ^= h >> 31;
    }
    return size_t(h);
  }
};

// The soup's corners by the position the repair gave their points: the
// first at each position, and the rest chained from it.
class CornersByPosition {
 public:
  CornersByPosition(const PolygonSoup& soup, const std::vector<glm::dvec3>& placed)
      : next_(soup.corners.size(), kNone), polygon_of_(soup.corners.size()) {
    for (size_t p = 0; p < soup.polygon_count(); ++p)
      std::fill(polygon_of_.begin() + soup.polygon_starts[p], polygon_of_.begin() + soup.polygon_starts[p + 1], uint32_t(p));
    first_.reserve(placed.size());
    for (size_t c = soup.corners.size(); c-- > 0;) {
      const auto [at, added] = first_.try_emplace(placed[soup.corners[c]], uint32_t(c));
      if (!added) next_[c] = std::exchange(at->second, uint32_t(c));
    }
  }

  uint32_t polygon_of(uint32_t corner) const { return polygon_of_[corner]; }

  // A corner of `polygon` at `position`, or kNone.
  uint32_t corner_of(uint32_t polygon, const glm::dvec3& position) const {
    const auto at = first_.find(position);
    for (uint32_t c = at == first_.end() ? kNone : at->second; c != kNone; c = next_[c])
      if (polygon_of_[c] == polygon) return c;
    return kNone;
  }

  // The soup corners of one polygon at the three corners of `triangle`, or
  // all kNone when no polygon has a corner at each.
  std::array<uint32_t, 3> origin_of(const std::array<glm::dvec3, 3>& triangle) const {
    const auto at = first_.find(triangle[0]);
    for (uint32_t c = at == first_.end() ? kNone : at->second; c != kNone; c = next_[c]) {
      const uint32_t b = corner_of(polygon_of_[c], triangle[1]);
      const uint32_t d = b == kNone ? kNone : corner_of(polygon_of_[c], triangle[2]);
      if (d != kNone) return {c, b, d};
    }
    return {kNone, kNone, kNone};
  }

 private:
  std::unordered_map<glm::dvec3, uint32_t, PositionHash> first_;
  std::vector<uint32_t> next_;
  std::vector<uint32_t> polygon_of_;
};

// Gives each point without a soup corner the corner of the nearest point,
// by edges, that has one (a breadth-first search from all of them at once).
void spread_to_the_rest(const std::vector<std::array<uint32_t, 3>>& triangles, std::vector<uint32_t>& corner_of_point) {
  std::vector<uint32_t> first(corner_of_point.size() + 1, 0);
  for (const auto& t : triangles)
    for (const uint32_t v : t) first[v + 1] += 2;
  for (size_t v = 0; v < corner_of_point.size(); ++v) first[v + 1] += first[v];
  std::vector<uint32_t> neighbours(first.back()), filled(first.begin(), first.end() - 1);
  for (const auto& t : triangles)
    for (size_t k = 0; k < 3; ++k) {
      neighbours[filled[t[k]]++] = t[(k + 1) % 3];
      neighbours[filled[t[k]]++] = t[(k + 2) % 3];
    }
  std::vector<uint32_t> queue;
  for (uint32_t v = 0; v < corner_of_point.size(); ++v)
    if (corner_of_point[v] != kNone) queue.push_back(v);
  for (size_t head = 0; head < queue.size(); ++head) {
    const uint32_t v = queue[head];
    for (uint32_t n = first[v]; n < first[v + 1]; ++n)
      if (corner_of_point[neighbours[n]] == kNone) {
        corner_of_point[neighbours[n]] = corner_of_point[v];
        queue.push_back(neighbours[n]);
      }
  }
}

// The most common of the three corners' materials (-1 for none).
int most_common_material(const PolygonSoup& soup, const CornersByPosition& corners, const std::array<uint32_t, 3>& origin) {
  std::array<int, 3> materials;
  for (size_t k = 0; k < 3; ++k) materials[k] = origin[k] == kNone ? -1 : soup.polygon_material(corners.polygon_of(origin[k]));
  return materials[1] == materials[2] ? materials[1] : materials[0];
}

}  // namespace

TriangleFile with_soup_attributes(const PolygonSoup& soup, const std::vector<glm::dvec3>& placed, std::vector<glm::dvec3> points,
                                  std::vector<std::array<uint32_t, 3>> triangles) {
  TriangleFile file;
  file.points = std::move(points);
  file.triangles = std::move(triangles);
  if (soup.materials.empty() && soup.corner_uvs.empty() && soup.point_colors.empty() && soup.corner_normals.empty()) return file;

  const CornersByPosition corners(soup, placed);
  std::vector<std::array<uint32_t, 3>> origin(file.triangles.size());
  std::vector<uint8_t> on_a_polygon(file.triangles.size());
  std::vector<uint32_t> corner_of_point(file.points.size(), kNone);
  bool all_found = true;
  for (size_t t = 0; t < file.triangles.size(); ++t) {
    const auto& triangle = file.triangles[t];
    origin[t] = corners.origin_of({file.points[triangle[0]], file.points[triangle[1]], file.points[triangle[2]]});
    on_a_polygon[t] = origin[t][0] != kNone;
    all_found = all_found && on_a_polygon[t];
    for (size_t k = 0; k < 3 && on_a_polygon[t]; ++k)
      if (corner_of_point[triangle[k]] == kNone) corner_of_point[triangle[k]] = origin[t][k];
  }
  if (!all_found) {
    spread_to_the_rest(file.triangles, corner_of_point);
    for (size_t t = 0; t < file.triangles.size(); ++t)
      if (!on_a_polygon[t])
        for (size_t k = 0; k < 3; ++k) origin[t][k] = corner_of_point[file.triangles[t][k]];
  }

  if (!soup.materials.empty()) {
    file.materials = soup.materials;
    file.triangle_materials.resize(file.triangles.size());
    for (size_t t = 0; t < file.triangles.size(); ++t)
      file.triangle_materials[t] = on_a_polygon[t] ? soup.polygon_material(corners.polygon_of(origin[t][0]))
                                                   : most_common_material(soup, corners, origin[t]);
  }
  if (!soup.corner_uvs.empty()) {
    file.corner_uvs.resize(3 * file.triangles.size());
    for (size_t t = 0; t < file.triangles.size(); ++t)
      for (size_t k = 0; k < 3; ++k)
        file.corner_uvs[3 * t + k] = origin[t][k] == kNone ? glm::vec2(0.0f) : soup.corner_uvs[origin[t][k]];
  }
  if (!soup.corner_normals.empty()) {
    file.corner_normals.resize(3 * file.triangles.size());
    for (size_t t = 0; t < file.triangles.size(); ++t) {
      const auto& triangle = file.triangles[t];
      const glm::dvec3 facing = glm::cross(file.points[triangle[1]] - file.points[triangle[0]], file.points[triangle[2]] - file.points[triangle[0]]);
      for (size_t k = 0; k < 3; ++k) {
        // A patch borrows no normal: one from the faces round a hole
        // would shade it as if it curved their way.
        const glm::vec3 normal = on_a_polygon[t] ? soup.corner_normals[origin[t][k]] : glm::vec3(0.0f);
        file.corner_normals[3 * t + k] = glm::dot(glm::dvec3(normal), facing) < 0.0 ? -normal : normal;
      }
    }
  }
  if (!soup.point_colors.empty()) {
    file.point_colors.assign(file.points.size(), glm::vec3(1.0f));
    for (size_t v = 0; v < file.points.size(); ++v)
      if (corner_of_point[v] != kNone && soup.corners[corner_of_point[v]] < soup.point_colors.size())
        file.point_colors[v] = soup.point_colors[soup.corners[corner_of_point[v]]];
  }
  return file;
}

}  // namespace umbra
