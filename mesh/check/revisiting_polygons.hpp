#pragma once
// Polygons that visit one vertex twice, as exporters write a face with a hole
// (a "keyhole": the outline, a bridge in, the hole, the bridge back out). As
// one face it would be degenerate and dropped whole; split into triangles it
// covers what it was drawn to cover.

#include "mesh/io/polygon_soup.hpp"

namespace umbra {

// Whether some polygon of more than three corners names one point twice.
bool has_revisiting_polygons(const PolygonSoup& soup);

// The soup with each such polygon replaced by its triangles (ear clipping in
// its plane), in its place and on its line; triangles that repeat a point or
// have no area are dropped. Each split polygon adds a warning that counts
// both. Faces after a split one move up in the face numbering; lines stay.
PolygonSoup split_revisiting_polygons(const PolygonSoup& soup);

}  // namespace umbra
