#include "mesh/check/repair_attributes.hpp"

#include <algorithm>
#include <array>
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

// Where a repaired corner's attributes come from: a blend of up to three
// of the soup's corners (kNone for none), by weights that sum to 1.
struct Blend {
  std::array<uint32_t, 3> corners{kNone, kNone, kNone};
  glm::dvec3 weights{1.0, 0.0, 0.0};
  bool found() const { return corners[0] != kNone; }
  template <typename Value, typename Of>
  Value of(Of&& attribute) const {
    Value sum(0.0f);
    for (size_t k = 0; k < 3; ++k)
      if (corners[k] != kNone) sum += float(weights[k]) * attribute(corners[k]);
    return sum;
  }
};

// Gives each point without a blend the blend of the nearest point, by edges,
// that has one (a breadth-first search from all of them at once).
void spread_to_the_rest(const std::vector<std::array<uint32_t, 3>>& triangles, std::vector<Blend>& blend_of_point) {
  std::vector<uint32_t> first(blend_of_point.size() + 1, 0);
  for (const auto& t : triangles)
    for (const uint32_t v : t) first[v + 1] += 2;
  for (size_t v = 0; v < blend_of_point.size(); ++v) first[v + 1] += first[v];
  std::vector<uint32_t> neighbours(first.back()), filled(first.begin(), first.end() - 1);
  for (const auto& t : triangles)
    for (size_t k = 0; k < 3; ++k) {
      neighbours[filled[t[k]]++] = t[(k + 1) % 3];
      neighbours[filled[t[k]]++] = t[(k + 2) % 3];
    }
  std::vector<uint32_t> queue;
  for (uint32_t v = 0; v < blend_of_point.size(); ++v)
    if (blend_of_point[v].found()) queue.push_back(v);
  for (size_t head = 0; head < queue.size(); ++head) {
    const uint32_t v = queue[head];
    for (uint32_t n = first[v]; n < first[v + 1]; ++n)
      if (!blend_of_point[neighbours[n]].found()) {
        blend_of_point[neighbours[n]] = blend_of_point[v];
        queue.push_back(neighbours[n]);
      }
  }
}

// The barycentric coordinates of `p` in the triangle (a, b, c), p taken
// onto its plane.
glm::dvec3 barycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  // A corner's own point takes its attributes exactly, not to rounding.
  if (p == a) return {1.0, 0.0, 0.0};
  if (p == b) return {0.0, 1.0, 0.0};
  if (p == c) return {0.0, 0.0, 1.0};
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double area = glm::dot(n, n);
  if (area == 0.0) return {1.0, 0.0, 0.0};
  const double u = glm::dot(glm::cross(c - b, p - b), n) / area, v = glm::dot(glm::cross(a - c, p - c), n) / area;
  return {u, v, 1.0 - u - v};
}

}  // namespace

TriangleFile with_soup_attributes(const PolygonSoup& soup, const std::vector<glm::dvec3>& placed, std::vector<glm::dvec3> points,
                                  std::vector<std::array<uint32_t, 3>> triangles,
                                  const std::vector<std::array<glm::dvec3, 3>>& split_from) {
  TriangleFile file;
  file.points = std::move(points);
  file.triangles = std::move(triangles);
  file.length_unit = soup.length_unit;
  if (soup.materials.empty() && soup.corner_uvs.empty() && soup.point_colors.empty() && soup.corner_normals.empty() && soup.parts.empty())
    return file;

  const CornersByPosition corners(soup, placed);
  enum class Found : uint8_t { kOnAPolygon, kCutFromOne, kNot };
  std::vector<Found> found(file.triangles.size(), Found::kNot);
  std::vector<uint32_t> polygon(file.triangles.size(), kNone);
  std::vector<std::array<Blend, 3>> blends(file.triangles.size());
  std::vector<Blend> blend_of_point(file.points.size());
  bool all_found = true;
  for (size_t t = 0; t < file.triangles.size(); ++t) {
    const auto& triangle = file.triangles[t];
    const std::array<glm::dvec3, 3> at = {file.points[triangle[0]], file.points[triangle[1]], file.points[triangle[2]]};
    if (const std::array<uint32_t, 3> origin = corners.origin_of(at); origin[0] != kNone) {
      found[t] = Found::kOnAPolygon;
      for (size_t k = 0; k < 3; ++k) blends[t][k].corners[0] = origin[k];
    } else if (!split_from.empty()) {
      const std::array<glm::dvec3, 3>& from = split_from[t];
      if (const std::array<uint32_t, 3> cut = corners.origin_of(from); cut[0] != kNone) {
        found[t] = Found::kCutFromOne;
        for (size_t k = 0; k < 3; ++k) blends[t][k] = {cut, barycentric(at[k], from[0], from[1], from[2])};
      }
    }
    if (found[t] == Found::kNot) {
      all_found = false;
      continue;
    }
    polygon[t] = corners.polygon_of(blends[t][0].corners[0]);
    for (size_t k = 0; k < 3; ++k)
      if (!blend_of_point[triangle[k]].found()) blend_of_point[triangle[k]] = blends[t][k];
  }
  if (!all_found) {
    spread_to_the_rest(file.triangles, blend_of_point);
    for (size_t t = 0; t < file.triangles.size(); ++t)
      if (found[t] == Found::kNot)
        for (size_t k = 0; k < 3; ++k) blends[t][k] = blend_of_point[file.triangles[t][k]];
  }

  // Each triangle's polygon's value of `of_polygon` (a material, a part);
  // a patch takes the one most of its corners' sources have.
  const auto per_triangle = [&](const std::vector<int>& of_polygon) {
    const auto value = [&](size_t p) { return p < of_polygon.size() ? of_polygon[p] : -1; };
    std::vector<int> values(file.triangles.size());
    for (size_t t = 0; t < file.triangles.size(); ++t) {
      std::array<int, 3> source;
      for (size_t k = 0; k < 3; ++k) source[k] = blends[t][k].found() ? value(corners.polygon_of(blends[t][k].corners[0])) : -1;
      values[t] = polygon[t] != kNone ? value(polygon[t]) : source[1] == source[2] ? source[1] : source[0];
    }
    return values;
  };
  if (!soup.materials.empty()) {
    file.materials = soup.materials;
    file.triangle_materials = per_triangle(soup.polygon_materials);
  }
  if (!soup.parts.empty()) {
    file.parts = soup.parts;
    file.triangle_parts = per_triangle(soup.polygon_parts);
  }
  if (!soup.corner_uvs.empty()) {
    file.corner_uvs.resize(3 * file.triangles.size());
    for (size_t t = 0; t < file.triangles.size(); ++t)
      for (size_t k = 0; k < 3; ++k)
        file.corner_uvs[3 * t + k] = blends[t][k].of<glm::vec2>([&](uint32_t c) { return soup.corner_uvs[c]; });
  }
  if (!soup.corner_normals.empty()) {
    file.corner_normals.resize(3 * file.triangles.size());
    for (size_t t = 0; t < file.triangles.size(); ++t) {
      const auto& triangle = file.triangles[t];
      const glm::dvec3 facing = glm::cross(file.points[triangle[1]] - file.points[triangle[0]], file.points[triangle[2]] - file.points[triangle[0]]);
      for (size_t k = 0; k < 3; ++k) {
        // A patch borrows no normal: one from the faces round a hole
        // would shade it as if it curved their way.
        glm::vec3 normal(0.0f);
        if (found[t] != Found::kNot) normal = blends[t][k].of<glm::vec3>([&](uint32_t c) { return soup.corner_normals[c]; });
        if (found[t] == Found::kCutFromOne && glm::dot(normal, normal) > 0.0f) normal = glm::normalize(normal);
        file.corner_normals[3 * t + k] = glm::dot(glm::dvec3(normal), facing) < 0.0 ? -normal : normal;
      }
    }
  }
  if (!soup.point_colors.empty()) {
    file.point_colors.assign(file.points.size(), glm::vec3(1.0f));
    for (size_t v = 0; v < file.points.size(); ++v)
      if (blend_of_point[v].found())
        file.point_colors[v] = blend_of_point[v].of<glm::vec3>([&](uint32_t c) {
          return soup.corners[c] < soup.point_colors.size() ? soup.point_colors[soup.corners[c]] : glm::vec3(1.0f);
        });
  }
  return file;
}

}  // namespace umbra
