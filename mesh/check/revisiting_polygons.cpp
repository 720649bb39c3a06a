#include "mesh/check/revisiting_polygons.hpp"

#include <algorithm>
#include <array>

#include "mesh/check/polygon_triangulation.hpp"
#include "mesh/predicates/orientation.hpp"

namespace umbra {
namespace {

bool revisits(const uint32_t* corners, uint32_t count) {
  if (count <= 3) return false;  // a triangle that repeats a point is plain degenerate
  if (count <= 8) {  // quads and their like, without an allocation each
    for (uint32_t i = 0; i < count; ++i)
      for (uint32_t j = i + 1; j < count; ++j)
        if (corners[i] == corners[j]) return true;
    return false;
  }
  std::vector<uint32_t> sorted(corners, corners + count);
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

}  // namespace

bool has_revisiting_polygons(const PolygonSoup& soup) {
  for (size_t p = 0; p < soup.polygon_count(); ++p)
    if (revisits(soup.polygon(p), soup.corner_count(p))) return true;
  return false;
}

PolygonSoup split_revisiting_polygons(const PolygonSoup& soup) {
  PolygonSoup split;
  split.path = soup.path;
  split.format = soup.format;
  split.points = soup.points;
  split.point_lines = soup.point_lines;
  split.warnings = soup.warnings;
  split.materials = soup.materials;
  const bool has_materials = !soup.polygon_materials.empty();
  split.corners.reserve(soup.corners.size());
  std::vector<std::array<uint32_t, 3>> triangles;
  for (size_t p = 0; p < soup.polygon_count(); ++p) {
    const uint32_t* corners = soup.polygon(p);
    const uint32_t count = soup.corner_count(p);
    const int line = soup.polygon_line(p);
    if (!revisits(corners, count)) {
      split.corners.insert(split.corners.end(), corners, corners + count);
      split.end_polygon(line);
      if (has_materials) split.polygon_materials.push_back(soup.polygon_materials[p]);
      continue;
    }
    triangles.clear();
    triangulate_polygon(soup.points, corners, count, triangles);
    size_t dropped = 0;
    for (const auto& [a, b, c] : triangles) {
      if (a == b || b == c || c == a || collinear(soup.points[a], soup.points[b], soup.points[c])) {
        ++dropped;
        continue;
      }
      split.corners.insert(split.corners.end(), {a, b, c});
      split.end_polygon(line);
      if (has_materials) split.polygon_materials.push_back(soup.polygon_materials[p]);
    }
    split.warn(line, "face " + std::to_string(p) + " (" + std::to_string(count) +
                         " corners) visits a vertex more than once: read as " +
                         std::to_string(triangles.size() - dropped) + " triangles" +
                         (dropped ? " (" + std::to_string(dropped) + " without area dropped)" : ""));
  }
  return split;
}

}  // namespace umbra
