#pragma once
// `umbra check`'s analysis: is a mesh a closed, consistently oriented
// 2-manifold without self-intersections, and if not, exactly why and where.

#include <array>
#include <vector>

#include <optional>

#include "mesh/check/mesh_report.hpp"
#include "mesh/check/triangle_topology.hpp"
#include "mesh/io/polygon_soup.hpp"
#include "mesh/topology/back_faces.hpp"

namespace umbra {

struct CheckOptions {
  // The search for self-intersections stops after this long and says so;
  // 0 skips it.
  double self_intersection_seconds = 60.0;
  // Also hand over the triangles' edge table and which components cast from
  // their silhouette, for the renderer (triangle_topology.hpp).
  bool triangle_topology = false;
  // With the search skipped (self_intersection_seconds 0): decide for the
  // renderer whether it may cull the mesh's back faces
  // (MeshAnalysis::back_faces). Where every component is closed, and would
  // face out as loaded were none to cross itself, that is left to the
  // picture; where some would be turned round, search all the same, without
  // a time limit, so that which way they face is decided.
  bool decide_back_faces = false;
  // How many offending elements of each kind the report lists
  // (MeshReport::examples): a few to find in the file, or every one for a
  // caller that marks them all (the Python module's defect arrays).
  size_t max_examples = MeshReport::kMaxExamples;
};

// The report, and the mesh as the renderer takes it: coincident points
// merged, faces that repeat a vertex and duplicate faces dropped, every other
// face triangulated and turned to agree with its neighbours (the fewest flips;
// a non-orientable component keeps the file's orientation), and every closed
// component turned to face outward.
struct MeshAnalysis {
  MeshReport report;
  std::vector<glm::dvec3> positions;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> triangle_face;  // the file's face each triangle comes from
  // The file's own materials, when its faces have any: one index into
  // `materials` per triangle, -1 for a face the file gives none.
  std::vector<SoupMaterial> materials;
  std::vector<int> triangle_materials;
  // Per triangle, its three corners' colours, when the file gives its points
  // colours (PolygonSoup::point_colors); empty otherwise.
  std::vector<std::array<glm::vec3, 3>> triangle_colors;
  // Per triangle, its corners' texture coordinates (PolygonSoup::corner_uvs),
  // when some material has a texture map; empty otherwise.
  std::vector<std::array<glm::vec2, 3>> triangle_uvs;
  // Per triangle, its corners' normals as the file gives them
  // (PolygonSoup::corner_normals), (0, 0, 0) where it gives none. Empty: none.
  std::vector<std::array<glm::vec3, 3>> triangle_normals;
  std::optional<TriangleTopology> topology;  // of `triangles`, with CheckOptions::triangle_topology
  BackFaces back_faces = BackFaces::kDrawn;  // with CheckOptions::decide_back_faces
};

MeshAnalysis analyse_mesh(const PolygonSoup& soup, const CheckOptions& options = {});
MeshReport check_mesh(const PolygonSoup& soup, const CheckOptions& options = {});
// The same, taking the soup apart as it goes (its points freed once merged,
// its corners reused): a soup read from a file is the largest thing the
// check holds.
MeshAnalysis analyse_mesh(PolygonSoup&& soup, const CheckOptions& options = {});
MeshReport check_mesh(PolygonSoup&& soup, const CheckOptions& options = {});

}  // namespace umbra
