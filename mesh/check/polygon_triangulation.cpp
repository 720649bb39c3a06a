#include "mesh/check/polygon_triangulation.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace umbra {
namespace {

double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool inside_or_on(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return cross2(a, b, p) >= 0.0 && cross2(b, c, p) >= 0.0 && cross2(c, a, p) >= 0.0;
}

void fan(const uint32_t* corners, uint32_t count, std::vector<std::array<uint32_t, 3>>& triangles) {
  for (uint32_t k = 1; k + 1 < count; ++k) triangles.push_back({corners[0], corners[k], corners[k + 1]});
}

}  // namespace

void triangulate_polygon(const std::vector<glm::dvec3>& positions, const uint32_t* corners, uint32_t count,
                         std::vector<std::array<uint32_t, 3>>& triangles) {
  if (count <= 4) {
    // A triangle, or a quad split along the diagonal that keeps both halves
    // on the polygon's side (the other one leaves a non-convex quad).
    if (count == 4) {
      const glm::dvec3& a = positions[corners[0]];
      const glm::dvec3& b = positions[corners[1]];
      const glm::dvec3& c = positions[corners[2]];
      const glm::dvec3& d = positions[corners[3]];
      const glm::dvec3 normal = glm::cross(c - a, d - b);
      const bool split_at_a = glm::dot(glm::cross(b - a, c - a), normal) > 0.0 && glm::dot(glm::cross(c - a, d - a), normal) > 0.0;
      if (!split_at_a) {
        triangles.push_back({corners[1], corners[2], corners[3]});
        triangles.push_back({corners[1], corners[3], corners[0]});
        return;
      }
    }
    fan(corners, count, triangles);
    return;
  }
  // Newell's normal; project onto the plane of its two smaller axes.
  glm::dvec3 normal(0.0);
  for (uint32_t k = 0; k < count; ++k) {
    const glm::dvec3& p = positions[corners[k]];
    const glm::dvec3& q = positions[corners[(k + 1) % count]];
    normal += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
  }
  const glm::dvec3 magnitude = glm::abs(normal);
  const int drop = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0 : magnitude.y >= magnitude.z ? 1 : 2;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double flip = normal[drop] < 0.0 ? -1.0 : 1.0;  // makes the polygon counter-clockwise in (u, v)
  std::vector<glm::dvec2> flat(count);
  for (uint32_t k = 0; k < count; ++k) flat[k] = {positions[corners[k]][u], flip * positions[corners[k]][v]};

  std::vector<uint32_t> remaining(count);
  for (uint32_t k = 0; k < count; ++k) remaining[k] = k;
  const size_t first_triangle = triangles.size();
  while (remaining.size() > 3) {
    bool clipped = false;
    const size_t n = remaining.size();
    for (size_t i = 0; i < n && !clipped; ++i) {
      const uint32_t ia = remaining[(i + n - 1) % n], ib = remaining[i], ic = remaining[(i + 1) % n];
      if (cross2(flat[ia], flat[ib], flat[ic]) <= 0.0) continue;  // reflex or flat corner
      bool empty = true;
      for (uint32_t other : remaining) {
        // A polygon that revisits a point (a keyhole's bridge) has that
        // point at two corners; its other copy does not block the ear.
        if (other == ia || other == ib || other == ic) continue;
        if (corners[other] == corners[ia] || corners[other] == corners[ib] || corners[other] == corners[ic]) continue;
        if (inside_or_on(flat[other], flat[ia], flat[ib], flat[ic])) empty = false;
      }
      if (!empty) continue;
      triangles.push_back({corners[ia], corners[ib], corners[ic]});
      remaining.erase(remaining.begin() + std::ptrdiff_t(i));
      clipped = true;
    }
    if (!clipped) {
      triangles.resize(first_triangle);
      fan(corners, count, triangles);
      return;
    }
  }
  triangles.push_back({corners[remaining[0]], corners[remaining[1]], corners[remaining[2]]});
}

FaceTriangles triangulate_faces(const PolygonSoup& soup, const FaceClasses& faces, const std::vector<glm::dvec3>& positions) {
  FaceTriangles out;
  size_t count = 0;  // a polygon of n corners makes n - 2 triangles
  for (uint32_t f = 0; f < soup.polygon_count(); ++f)
    if (faces.in_topology(f)) count += soup.corner_count(f) - 2;
  out.triangles.reserve(count);
  out.face.reserve(count);
  for (uint32_t f = 0; f < soup.polygon_count(); ++f) {
    if (!faces.in_topology(f)) continue;
    const size_t first = out.triangles.size();
    triangulate_polygon(positions, faces.corners.data() + soup.polygon_starts[f], soup.corner_count(f), out.triangles);
    out.face.insert(out.face.end(), out.triangles.size() - first, f);
  }
  return out;
}

}  // namespace umbra
