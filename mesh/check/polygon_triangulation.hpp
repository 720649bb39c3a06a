#pragma once
// Splitting polygons into triangles: each polygon on its own, and a file's
// faces as the triangles that the renderer and the geometric tests (self-
// intersections, volume) use.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/check/face_classes.hpp"
#include "mesh/io/polygon_soup.hpp"

namespace umbra {

// Appends the triangles of the polygon with `count` corners (indices into
// `positions`). Ear clipping in the plane of the polygon's Newell normal, so
// that a non-convex planar polygon is split inside itself; a fan from the
// first corner when no ear can be found (a polygon that crosses itself).
void triangulate_polygon(const std::vector<glm::dvec3>& positions, const uint32_t* corners, uint32_t count,
                         std::vector<std::array<uint32_t, 3>>& triangles);

struct FaceTriangles {
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> face;  // the file's face each triangle comes from
};
// The faces in the topology as triangles, as the file winds them. Faces
// whose corners are collinear stay: a closed mesh needs them.
FaceTriangles triangulate_faces(const PolygonSoup& soup, const FaceClasses& faces, const std::vector<glm::dvec3>& positions);

}  // namespace umbra
