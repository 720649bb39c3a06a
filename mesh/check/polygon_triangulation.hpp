#pragma once
// Splitting a polygon into triangles for the geometric tests (self-
// intersections, volume) while the topology stays on the polygons as written.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

// Appends the triangles of the polygon with `count` corners (indices into
// `positions`). Ear clipping in the plane of the polygon's Newell normal, so
// that a non-convex planar polygon is split inside itself; a fan from the
// first corner when no ear can be found (a polygon that crosses itself).
void triangulate_polygon(const std::vector<glm::dvec3>& positions, const uint32_t* corners, uint32_t count,
                         std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace umbra
