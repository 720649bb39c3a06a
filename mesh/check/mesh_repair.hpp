#pragma once
// `umbra check --repair`: what CGAL's Polygon Mesh Processing can fix.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/io/mesh_writers.hpp"
#include "mesh/io/polygon_soup.hpp"

namespace umbra {

struct RepairSummary {
  std::vector<std::string> changes;  // one line per kind of change made, e.g. "merged 24 repeated vertices"
  // What the written mesh names beside it (an OBJ's material library, its
  // maps), for the caller to write whole before it renames the mesh into place.
  std::vector<CompanionFile> companions;
};

// Whether the repair can write a mesh to `path`, by its extension: .obj,
// .off, .ply or .stl (any case), the formats whose table row has a writer;
// not glTF or 3MF.
bool repair_can_write(const std::string& path);

// Holes of more edges than this are left open unless --max-hole-edges says:
// a hole that large is more often an opening the model means (a cup, a
// scan's base) than a defect, and filling it costs time cubic in its edges.
constexpr size_t kDefaultMaxHoleEdges = 200;

// Merges repeated vertices (and, with a tolerance, nearby ones), drops degenerate and duplicate faces and unused
// vertices, splits non-manifold vertices, orients faces consistently, stitches
// borders that coincide, triangulates, fills each hole of at most
// `max_hole_edges` edges (hole_filling.hpp), and turns every closed
// component outward; writes the result to `write_to`, a file whose extension is
// `output`'s and chooses the format (the caller renames it to `output` once
// whole), with what the format keeps of the soup's materials, texture
// coordinates, colours and normals (repair_attributes.hpp; the summary says
// what it could not keep). Throws InputError, located at `output`, when
// nothing usable is left or the file cannot be written.
struct RepairOptions {
  size_t max_hole_edges = kDefaultMaxHoleEdges;
  // Points at most this far apart (in the model's units) are one before
  // anything else is done (merge_nearby_points); 0: only equal ones.
  double merge_tolerance = 0.0;
};

RepairSummary repair_mesh(const PolygonSoup& soup, const std::string& output, const std::string& write_to,
                          const RepairOptions& options = {});

// The same repair, its result handed back rather than written: the
// surface's points and triangles (every face is a triangle once repaired).
struct RepairedTriangles {
  RepairSummary summary;
  std::vector<glm::dvec3> points;
  std::vector<std::array<uint32_t, 3>> triangles;
};
RepairedTriangles repair_to_triangles(const PolygonSoup& soup, const RepairOptions& options = {});

}  // namespace umbra
