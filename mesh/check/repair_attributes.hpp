#pragma once
// What a repaired surface keeps of its file's look: its materials, texture
// coordinates, vertex colours and shading normals, carried over from the
// polygons of the soup that each repaired triangle lies on.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/io/mesh_writers.hpp"
#include "mesh/io/polygon_soup.hpp"

namespace umbra {

// `points` and `triangles`, a repair of `soup`, with the soup's attributes.
// `placed` is where the repair put each of the soup's points (a merge within
// a tolerance moves some; otherwise the soup's own points). A triangle whose
// three corners are corners of one soup polygon takes that polygon's
// material and those corners' attributes: the repair moves no point but by
// merging, so each kept triangle is found by its corners' positions, however
// the repair renumbered, reoriented, split or stitched them. A triangle cut
// from a larger one (`split_from`, per triangle, the points of the one it
// was cut from; empty when none was cut) takes that one's material and, at
// each corner, its attributes interpolated there. A triangle found on no
// polygon (a hole's patch, a triangle an edge flip made) takes, at each
// corner, the attributes of the nearest point that has them, nearest by
// edges, and its corners' most common material, but no shading normals (it
// is drawn flat). Shading normals are turned to the side their triangle
// faces, since the repair may have turned it.
TriangleFile with_soup_attributes(const PolygonSoup& soup, const std::vector<glm::dvec3>& placed, std::vector<glm::dvec3> points,
                                  std::vector<std::array<uint32_t, 3>> triangles,
                                  const std::vector<std::array<glm::dvec3, 3>>& split_from = {});

}  // namespace umbra
