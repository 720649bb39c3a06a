#pragma once
// The check's triangle topology (CheckOptions::triangle_topology) must be
// exactly what the renderer's own pass makes of the analysed triangles.

#include <gtest/gtest.h>

#include "mesh/check/mesh_check.hpp"
#include "mesh/topology/silhouette_components.hpp"
#include "mesh/topology/edge_table.hpp"

namespace umbra::test {

// Analyses `soup` with the topology asked for; where the check gives one,
// expects it equal to build_edge_table and find_silhouette_components on the
// triangles, field by field. Returns whether it gave one.
inline bool expect_triangle_topology_as_built(const PolygonSoup& soup) {
  CheckOptions options;
  options.self_intersection_seconds = 0.0;
  options.triangle_topology = true;
  const MeshAnalysis a = analyse_mesh(soup, options);
  if (!a.topology) return false;
  const EdgeTable edges = build_edge_table(a.triangles, a.positions.size());
  const SilhouetteComponents closed = find_silhouette_components(a.triangles, edges, a.positions.size());
  EXPECT_EQ(a.topology->edges.vertices, edges.vertices);
  EXPECT_EQ(a.topology->edges.first_use, edges.first_use);
  EXPECT_EQ(a.topology->edges.uses, edges.uses);
  const SilhouetteComponents& c = a.topology->components;
  EXPECT_EQ(c.silhouette_face, closed.silhouette_face);
  EXPECT_EQ(c.components, closed.components);
  EXPECT_EQ(c.silhouette_components, closed.silhouette_components);
  EXPECT_EQ(c.border_edges, closed.border_edges);
  EXPECT_EQ(c.border_loops, closed.border_loops);
  // Bare triangles cannot tell a polygon's diagonal from the file's edges.
  EXPECT_EQ(c.non_manifold_edges + c.overlapping_diagonals, closed.non_manifold_edges);
  EXPECT_EQ(c.inconsistent_edges, closed.inconsistent_edges);
  EXPECT_EQ(c.non_manifold_vertices, closed.non_manifold_vertices);
  return true;
}

}  // namespace umbra::test
