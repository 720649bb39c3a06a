#include "mesh/check/revisiting_polygons.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "mesh/check/polygon_triangulation.hpp"
#include "mesh/predicates/orientation.hpp"

namespace umbra {
namespace {

// Whether a polygon comes back to a place it has been: by position, not by
// index, since the file's points are merged before anything else (a bridge
// whose ends are written as separate but equal points is a bridge all the same).
bool revisits(const std::vector<glm::dvec3>& points, const uint32_t* corners, uint32_t count) {
  if (count <= 3) return false;  // a triangle that repeats a point is plain degenerate
  if (count <= 8) {  // quads and their like, without an allocation each
    for (uint32_t i = 0; i < count; ++i)
      for (uint32_t j = i + 1; j < count; ++j)
        if (points[corners[i]] == points[corners[j]]) return true;
    return false;
  }
  std::vector<std::array<double, 3>> sorted(count);
  for (uint32_t i = 0; i < count; ++i) sorted[i] = {points[corners[i]].x, points[corners[i]].y, points[corners[i]].z};
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

// " (466 without area and 466 repeats dropped)", or "" when none were.
std::string dropped_phrase(size_t without_area, size_t repeats) {
  if (!without_area && !repeats) return "";
  std::string s = " (";
  if (without_area) s += std::to_string(without_area) + " without area";
  if (without_area && repeats) s += " and ";
  if (repeats) s += std::to_string(repeats) + (repeats == 1 ? " repeat" : " repeats");
  return s + " dropped)";
}

}  // namespace

bool has_revisiting_polygons(const PolygonSoup& soup) {
  for (size_t p = 0; p < soup.polygon_count(); ++p)
    if (revisits(soup.points, soup.polygon(p), soup.corner_count(p))) return true;
  return false;
}

PolygonSoup split_revisiting_polygons(const PolygonSoup& soup) {
  PolygonSoup split;
  split.path = soup.path;
  split.format = soup.format;
  split.points = soup.points;
  split.point_lines = soup.point_lines;
  split.point_colors = soup.point_colors;
  split.warnings = soup.warnings;
  split.materials = soup.materials;
  const bool has_materials = !soup.polygon_materials.empty();
  const bool has_uvs = !soup.corner_uvs.empty();
  const bool has_normals = !soup.corner_normals.empty();
  split.corners.reserve(soup.corners.size());
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> same_place;
  for (size_t p = 0; p < soup.polygon_count(); ++p) {
    const uint32_t* corners = soup.polygon(p);
    const uint32_t count = soup.corner_count(p);
    const int line = soup.polygon_line(p);
    if (!revisits(soup.points, corners, count)) {
      split.corners.insert(split.corners.end(), corners, corners + count);
      if (has_uvs) {
        const auto first = soup.corner_uvs.begin() + std::ptrdiff_t(soup.polygon_starts[p]);
        split.corner_uvs.insert(split.corner_uvs.end(), first, first + count);
      }
      if (has_normals) {
        const auto first = soup.corner_normals.begin() + std::ptrdiff_t(soup.polygon_starts[p]);
        split.corner_normals.insert(split.corner_normals.end(), first, first + count);
      }
      split.end_polygon(line);
      if (has_materials) split.polygon_materials.push_back(soup.polygon_materials[p]);
      continue;
    }
    // Each corner as the first of the polygon's corners at its place, so
    // that equal points written twice are one vertex to the triangulation.
    same_place.assign(corners, corners + count);
    std::map<std::array<double, 3>, uint32_t> first_at;
    for (uint32_t& corner : same_place) {
      const glm::dvec3& q = soup.points[corner];
      corner = first_at.emplace(std::array<double, 3>{q.x, q.y, q.z}, corner).first->second;
    }
    triangles.clear();
    triangulate_polygon(soup.points, same_place.data(), count, triangles);
    // A polygon that walks round the same loop again ("f 1 2 3 4 1 2 3 4
    // ...") covers its triangles again: each is kept once, and the repeats
    // are said here rather than counted as duplicate faces of the file.
    size_t dropped = 0, repeats = 0;
    std::set<std::array<uint32_t, 3>> kept;
    for (const auto& [a, b, c] : triangles) {
      if (a == b || b == c || c == a || collinear(soup.points[a], soup.points[b], soup.points[c])) {
        ++dropped;
        continue;
      }
      std::array<uint32_t, 3> corner_set{a, b, c};
      std::sort(corner_set.begin(), corner_set.end());
      if (!kept.insert(corner_set).second) {
        ++repeats;
        continue;
      }
      split.corners.insert(split.corners.end(), {a, b, c});
      // Each point's texture coordinates and normal at its first corner in the polygon.
      for (const uint32_t point : {a, b, c}) {
        const uint32_t corner = soup.polygon_starts[p] + uint32_t(std::find(corners, corners + count, point) - corners);
        if (has_uvs) split.corner_uvs.push_back(soup.corner_uvs[corner]);
        if (has_normals) split.corner_normals.push_back(soup.corner_normals[corner]);
      }
      split.end_polygon(line);
      if (has_materials) split.polygon_materials.push_back(soup.polygon_materials[p]);
    }
    split.warn(line, "face " + std::to_string(p) + " (" + std::to_string(count) +
                         " corners) visits a vertex more than once: read as " +
                         std::to_string(triangles.size() - dropped - repeats) + " triangles" + dropped_phrase(dropped, repeats));
  }
  return split;
}

}  // namespace umbra
