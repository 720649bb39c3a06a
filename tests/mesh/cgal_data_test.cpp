// `umbra check` against CGAL's own answers on the real meshes of Debian's
// CGAL data (libcgal-demo), unpacked at build time: for every mesh CGAL
// builds into a half-edge mesh, the same border edges, holes, components,
// closedness, self-intersection verdict and outward orientation; for every
// soup CGAL refuses, a report that says why; and for every mesh the check
// calls closed and consistently oriented, an OpenMesh half-edge mesh without
// border and with the same Euler characteristic.
#include <filesystem>
#include <iostream>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "mesh/topology/half_edge_mesh.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mesh_file.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/mesh/triangle_topology_expect.hpp"

namespace umbra {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

std::vector<std::string> cgal_meshes() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(UMBRA_CGAL_DATA "/meshes"))
    if (!mesh_format_of(entry.path().string()).empty()) paths.push_back(entry.path().string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

TEST(CgalData, EveryMeshIsReadAndAgreesWithCgal) {
  const std::vector<std::string> paths = cgal_meshes();
  ASSERT_GE(paths.size(), 100u) << "CGAL's data meshes are missing from " UMBRA_CGAL_DATA;
  size_t compared_as_meshes = 0, refused_soups = 0;
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    std::vector<Kernel::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    if (!CGAL::IO::read_polygon_soup(path, points, polygons)) continue;  // CGAL cannot read it either
    MeshAnalysis analysis;
    ASSERT_NO_THROW(analysis = analyse_mesh(read_polygon_soup(path)));
    const MeshReport& report = analysis.report;
    if (report.volume_kind() == VolumeKind::kSilhouette) {
      // OpenMesh takes every triangle, and finds no border.
      HalfEdgeMesh half_edges;
      ASSERT_NO_THROW(half_edges = build_half_edge_mesh(analysis.positions, analysis.triangles));
      size_t boundary = 0;
      for (const auto h : half_edges.halfedges()) boundary += half_edges.is_boundary(h);
      EXPECT_EQ(boundary, 0u);
      size_t isolated = 0;  // positions no face uses, which the report leaves out of V
      for (const auto v : half_edges.vertices()) isolated += half_edges.is_isolated(v);
      EXPECT_EQ(int64_t(half_edges.n_vertices() - isolated) - int64_t(half_edges.n_edges()) + int64_t(half_edges.n_faces()),
                report.euler_characteristic);
    }
    ASSERT_EQ(report.file_faces, polygons.size());
    if (mesh_format_of(path) != "stl") {  // CGAL's STL reader merges points
      EXPECT_EQ(report.file_vertices, points.size());
    }

    // The same soup as umbra sees it: equal points merged.
    PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
    Mesh mesh;
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
      ++refused_soups;
      // CGAL refuses it as a mesh: it is not a closed 2-manifold, or its faces disagree on their orientation.
      EXPECT_TRUE(report.volume_kind() != VolumeKind::kSilhouette || report.inconsistent_edges > 0);
      EXPECT_GT(report.non_manifold_edges + report.non_manifold_vertices + report.inconsistent_edges +
                    report.non_orientable_components + report.degenerate_faces + report.duplicate_faces,
                0u);
      continue;
    }
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    ++compared_as_meshes;
    std::vector<Mesh::Halfedge_index> cycles;
    PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
    size_t border_halfedges = 0;
    for (const auto h : mesh.halfedges()) border_halfedges += mesh.is_border(h);
    auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:c", 0).first;
    EXPECT_EQ(report.border_edges, border_halfedges);
    EXPECT_EQ(report.border_loops, cycles.size());
    EXPECT_EQ(report.components.size(), PMP::connected_components(mesh, component));
    EXPECT_EQ(report.non_manifold_edges + report.non_manifold_vertices + report.inconsistent_edges, 0u);
    const bool triangles = CGAL::is_triangle_mesh(mesh);
    const bool clean = triangles && report.degenerate_faces == 0;
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> crossing;
    if (clean) PMP::self_intersections(mesh, std::back_inserter(crossing));
    const bool self_intersects = !crossing.empty();
    if (clean) {
      // The same pairs as CGAL's own search, counted: the parallel search
      // misses none and reports none twice.
      EXPECT_EQ(report.self_intersections.face_pairs, crossing.size());
    }
    if (CGAL::is_closed(mesh) && clean && !self_intersects && mesh.number_of_faces() > 0) {
      // Every component, nested or not: the ones CGAL turns round to bound a
      // volume are the ones the check calls inward.
      Mesh oriented = mesh;
      PMP::orient_to_bound_a_volume(oriented);
      std::vector<uint8_t> turned(report.components.size(), 0);
      for (const auto f : mesh.faces()) {
        std::vector<Mesh::Vertex_index> before, after;
        for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) before.push_back(v);
        for (const auto v : CGAL::vertices_around_face(oriented.halfedge(f), oriented)) after.push_back(v);
        std::rotate(after.begin(), std::find(after.begin(), after.end(), before[0]), after.end());
        if (after != before) turned[component[f]] = 1;
      }
      EXPECT_EQ(report.inward_components, size_t(std::count(turned.begin(), turned.end(), 1)));
    }
  }
  std::cout << compared_as_meshes << " meshes compared with CGAL's, " << refused_soups << " soups CGAL refuses\n";
  // The comparison covered both kinds (numbers as of CGAL 5.5's data).
  EXPECT_GT(compared_as_meshes, 50u);
  EXPECT_GT(refused_soups, 0u);
}

// On every data mesh of triangles, the renderer's edge table and closed
// components taken from the check's pass equal those of a second pass.
TEST(CgalData, TriangleTopologyFromTheCheckEqualsASecondPass) {
  size_t given = 0;
  for (const std::string& path : cgal_meshes()) {
    SCOPED_TRACE(path);
    PolygonSoup soup;
    try {
      soup = read_polygon_soup(path);
    } catch (const InputError&) {
      continue;  // the unreadable ones are tested above
    }
    given += test::expect_triangle_topology_as_built(soup);
  }
  EXPECT_GT(given, 80u);
}

// Grids of squares split in two, their points shaken: a little, so that every
// star is a bumpy closed or open fan, or so much that fans fold over
// themselves and sheets pass through each other. The check's search skips
// pairs of triangles round stars it proves simple; it must still find exactly
// the pairs CGAL finds.
TEST(CgalData, ShakenGridsHaveExactlyTheSelfIntersectionsCgalFinds) {
  std::mt19937 random(11);
  for (const double shake : {0.1, 0.45, 0.8}) {
    SCOPED_TRACE(shake);
    constexpr int kSide = 40;
    std::uniform_real_distribution<double> jitter(-shake, shake);
    std::vector<glm::dvec3> points;
    for (int i = 0; i < kSide; ++i)
      for (int j = 0; j < kSide; ++j) points.push_back({i + jitter(random), j + jitter(random), jitter(random)});
    // Two sheets, the second folded back over the first, so that the grids
    // cross each other as well as themselves.
    std::vector<test::Face> faces;
    const auto at = [](int i, int j) { return uint32_t(i * kSide + j); };
    for (int i = 0; i + 1 < kSide; ++i)
      for (int j = 0; j + 1 < kSide; ++j) {
        faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    const size_t sheet = points.size();
    for (size_t p = 0; p < sheet; ++p) points.push_back({points[p].y, points[p].x, 0.5 + points[p].z});
    const size_t sheet_faces = faces.size();
    for (size_t f = 0; f < sheet_faces; ++f)
      faces.push_back({uint32_t(faces[f][0] + sheet), uint32_t(faces[f][1] + sheet), uint32_t(faces[f][2] + sheet)});

    const MeshReport report = check_mesh(test::make_soup(points, faces));
    std::vector<Kernel::Point_3> cgal_points;
    for (const glm::dvec3& p : points) cgal_points.emplace_back(p.x, p.y, p.z);
    std::vector<std::vector<std::size_t>> polygons;
    for (const test::Face& f : faces) polygons.push_back({f[0], f[1], f[2]});
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(cgal_points, polygons, mesh);
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> crossing;
    PMP::self_intersections(mesh, std::back_inserter(crossing));
    EXPECT_EQ(report.degenerate_faces, 0u);
    EXPECT_EQ(report.self_intersections.face_pairs, crossing.size());
    if (shake > 0.4) {
      EXPECT_GT(crossing.size(), 100u);  // the folds are there to be found
    }
  }
}

}  // namespace
}  // namespace umbra
