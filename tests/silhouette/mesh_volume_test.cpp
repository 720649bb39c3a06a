// Silhouettes and volumes of closed meshes against hand-computed edges, and
// closed, outward volumes for many lights.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <filesystem>
#include <random>
#include <set>

#include <tbb/task_arena.h>

#include "mesh/io/mesh_file.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mesh/predicates/orientation.hpp"
#include "silhouette/light_facing.hpp"
#include "silhouette/mesh_volume.hpp"
#include "silhouette/volume_topology.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

using namespace umbra::test;

MeshAdjacency adjacency_of(const PolygonSoup& soup) {
  const MeshAnalysis a = analyse_mesh(soup);
  return build_mesh_adjacency(a.positions, a.triangles);
}

bool less_point(const glm::dvec3& a, const glm::dvec3& b) {
  return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}
bool less_edge(const std::pair<glm::dvec3, glm::dvec3>& a, const std::pair<glm::dvec3, glm::dvec3>& b) {
  return less_point(a.first, b.first) || (a.first == b.first && less_point(a.second, b.second));
}
using EdgeSet = std::set<std::pair<glm::dvec3, glm::dvec3>, bool (*)(const std::pair<glm::dvec3, glm::dvec3>&,
                                                                      const std::pair<glm::dvec3, glm::dvec3>&)>;

EdgeSet silhouette_of(const MeshAdjacency& mesh, const glm::dvec3& light) {
  std::vector<uint8_t> facing;
  classify_light_facing(mesh, light, facing);
  EdgeSet edges(less_edge);
  for (const auto& [a, b] : silhouette_edges(mesh, facing)) edges.insert({mesh.positions[a], mesh.positions[b]});
  return edges;
}

// A closed loop through `corners` in order.
EdgeSet loop(const std::vector<glm::dvec3>& corners) {
  EdgeSet edges(less_edge);
  for (size_t i = 0; i < corners.size(); ++i) edges.insert({corners[i], corners[(i + 1) % corners.size()]});
  return edges;
}

const PolygonSoup kCube = box_quads(glm::dvec3(-1.0), glm::dvec3(1.0));

TEST(MeshSilhouette, CubeLitFromAboveOutlinesItsTopFace) {
  // Only the top face (z = 1) faces (0, 0, 5); its edges run counter-clockwise seen from above.
  EXPECT_EQ(silhouette_of(adjacency_of(kCube), {0, 0, 5}),
            loop({{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}));
}

TEST(MeshSilhouette, CubeLitAlongItsDiagonalOutlinesAHexagon) {
  // x = 1, y = 1 and z = 1 face (5, 5, 5); their outline skips the corner (1, 1, 1).
  EXPECT_EQ(silhouette_of(adjacency_of(kCube), {5, 5, 5}),
            loop({{1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}}));
}

TEST(MeshSilhouette, FaceWhosePlaneContainsTheLightDoesNotFaceIt) {
  // (3, 0, 1) lies in the plane of the top face: only x = 1 faces it, exactly.
  const MeshAdjacency cube = adjacency_of(kCube);
  EXPECT_EQ(silhouette_of(cube, {3, 0, 1}), loop({{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}}));
  // A hair above, the top face faces the light too; a hair below, it does not.
  EXPECT_EQ(silhouette_of(cube, {3, 0, 1 + 1e-15}), loop({{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}}));
  EXPECT_EQ(silhouette_of(cube, {3, 0, 1 - 1e-15}), silhouette_of(cube, {3, 0, 1}));
  for (const glm::dvec3& light : {glm::dvec3(3, 0, 1), glm::dvec3(3, 0, 1 + 1e-15), glm::dvec3(1, 1, 7)})
    EXPECT_TRUE(is_closed_and_consistently_oriented(mesh_shadow_volume(cube, light)));
}

TEST(MeshSilhouette, ClassificationAgreesWithTheExactPredicateForLightsOnAndNearAFacesPlane) {
  // Lights on the plane of a tetrahedron's face, as rounding puts them, and a
  // few units in the last place off it: where the plane test's rounding could
  // flip the sign, the exact predicate must have decided.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), far(-50.0, 50.0);
  int decided_near_zero = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const glm::dvec3 a(coordinate(random), coordinate(random), coordinate(random));
    const glm::dvec3 b(coordinate(random), coordinate(random), coordinate(random));
    const glm::dvec3 c(coordinate(random), coordinate(random), coordinate(random));
    const glm::dvec3 d = (a + b + c) / 3.0 + glm::normalize(glm::cross(b - a, c - a)) * -0.5;  // behind face abc
    const MeshAdjacency tetrahedron = adjacency_of(make_soup({a, b, c, d}, {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}}));
    glm::dvec3 light = a + far(random) * (b - a) + far(random) * (c - a);
    light.z = std::nextafter(light.z, trial % 3 == 0 ? 10.0 : -10.0);
    std::vector<uint8_t> facing;
    classify_light_facing(tetrahedron, light, facing);
    const int exact = orientation(a, b, c, light);
    EXPECT_EQ(facing[0], exact > 0) << "trial " << trial;
    decided_near_zero += std::abs(glm::dot(glm::cross(b - a, c - a), light - a)) < 1e-12;
  }
  EXPECT_GT(decided_near_zero, 1000) << "the lights should lie within rounding of the plane";
}

TEST(MeshSilhouette, OctahedronLitAlongAnAxisOutlinesTheSquareAcrossIt) {
  const MeshAdjacency octahedron = adjacency_of(test::octahedron());
  EXPECT_EQ(silhouette_of(octahedron, {0, 0, 10}), loop({{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}));
  EXPECT_EQ(silhouette_of(octahedron, {10, 0, 0}), loop({{0, -1, 0}, {0, 0, -1}, {0, 1, 0}, {0, 0, 1}}));
}

TEST(MeshSilhouette, SphereLitFromAboveOutlinesItsEquator) {
  // From (0, 0, 100) the tangent cone touches at z = 0.01: every band above
  // the equator tilts up and faces the light, every band below does not.
  const int segments = 16;
  const MeshAdjacency sphere = adjacency_of(uv_sphere(8, segments));
  std::vector<glm::dvec3> equator;
  for (int j = 0; j < segments; ++j) {
    const double azimuth = 2 * 3.141592653589793 * j / segments;
    equator.push_back({std::sin(3.141592653589793 / 2) * std::cos(azimuth), std::sin(3.141592653589793 / 2) * std::sin(azimuth),
                       std::cos(3.141592653589793 / 2)});
  }
  EXPECT_EQ(silhouette_of(sphere, {0, 0, 100}), loop(equator));
}

TEST(MeshVolume, CapsAndQuadsOfTheCubeLitFromAbove) {
  // The top face's 2 triangles face (0.5, 0.5, 5); the other 10 make both caps.
  const ShadowVolume v = mesh_shadow_volume(adjacency_of(unit_cube()), {0.5, 0.5, 5});
  EXPECT_EQ(v.side_quads, 4);
  EXPECT_EQ(v.light_cap_triangles, 10);
  EXPECT_EQ(v.dark_cap_triangles, 10);
  int near_cap = 0;
  for (const auto& tri : v.triangles) {
    if (v.vertices[tri[0]].w == 0.0 || v.vertices[tri[1]].w == 0.0 || v.vertices[tri[2]].w == 0.0) continue;
    ++near_cap;  // a near-cap triangle: a face turned away from the light, reversed to face it (or edge-on)
    EXPECT_GE(orientation(glm::dvec3(v.vertices[tri[0]]), glm::dvec3(v.vertices[tri[1]]), glm::dvec3(v.vertices[tri[2]]),
                          {0.5, 0.5, 5}),
              0);
    EXPECT_LT(glm::dvec3(v.vertices[tri[0]]).z + glm::dvec3(v.vertices[tri[1]]).z + glm::dvec3(v.vertices[tri[2]]).z, 3.0)
        << "the lit top face is not part of the volume";
  }
  EXPECT_EQ(near_cap, 10);
}

// Lights all around, 4 to 14 units from the centre.
std::vector<glm::dvec3> lights_around(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<glm::dvec3> lights;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 direction(unit(random), unit(random), unit(random));
    lights.push_back(glm::normalize(direction) * (4.0 + 10.0 * std::abs(unit(random))));
  }
  return lights;
}

TEST(MeshVolume, ConvexMeshesGiveClosedOrientedManifoldVolumes) {
  for (const PolygonSoup& soup : {unit_cube(), kCube, test::octahedron(), uv_sphere(8, 16), uv_sphere(5, 7),
                                   all_reversed(uv_sphere(6, 9))}) {
    const MeshAdjacency mesh = adjacency_of(soup);
    for (const glm::dvec3& light : lights_around(50, 4)) {
      const ShadowVolume v = mesh_shadow_volume(mesh, light);
      ASSERT_TRUE(is_closed_and_consistently_oriented(v)) << mesh.triangles.size() << " triangles, light " << light.x << " "
                                                          << light.y << " " << light.z;
      EXPECT_GE(v.side_quads, 3);
      std::vector<uint8_t> facing;
      classify_light_facing(mesh, light, facing);
      const int turned_away = int(std::count(facing.begin(), facing.end(), 0));
      EXPECT_EQ(v.light_cap_triangles, turned_away);
      EXPECT_EQ(v.dark_cap_triangles, turned_away);
    }
  }
}

TEST(MeshVolume, TorusVolumeHasNoBoundaryWhereSilhouetteLoopsMeet) {
  const MeshAdjacency torus = adjacency_of(quad_torus(12, 8));
  int loops_meet = 0;
  for (const glm::dvec3& light : lights_around(200, 5)) {
    const ShadowVolume v = mesh_shadow_volume(torus, light);
    ASSERT_TRUE(has_no_boundary(v)) << light.x << " " << light.y << " " << light.z;
    loops_meet += !is_closed_and_consistently_oriented(v);
  }
  EXPECT_GT(loops_meet, 0) << "no light made two silhouette loops meet: the test lost its point";
}

// A mesh of many blocks of faces and edges: the volume, made on every core,
// holds its caps in face order and its quads in edge order, as one loop
// over each would make them, whatever the threads, and has no boundary.
TEST(MeshVolume, MadeOnEveryCoreInTheOrderOfOneLoop) {
  const MeshAdjacency torus = adjacency_of(quad_torus(300, 200));  // 120,000 triangles, 180,000 edges
  const glm::dvec3 light(0.7, 1.9, 2.3);
  std::vector<uint8_t> facing;
  MeshVolumeIndices volume;
  mesh_volume_indices(torus, light, facing, volume);
  size_t k = 0;
  for (size_t t = 0; t < torus.triangles.size(); ++t) {
    if (facing[t]) continue;
    const auto& tri = torus.triangles[t];
    ASSERT_EQ(std::vector<uint32_t>(volume.buffer.begin() + k, volume.buffer.begin() + k + 3),
              (std::vector<uint32_t>{tri[0], tri[2], tri[1]})) << "cap of face " << t;
    k += 6;
  }
  EXPECT_EQ(k / 6, size_t(volume.light_cap_triangles));
  const auto edges = silhouette_edges(torus, facing);
  ASSERT_EQ(edges.size(), size_t(volume.side_quads));
  for (const auto& [a, b] : edges) {
    ASSERT_EQ(volume.buffer[k], b);
    ASSERT_EQ(volume.buffer[k + 1], a);
    k += 6;
  }
  EXPECT_EQ(k, volume.count);
  for (const int threads : {1, 3}) {
    MeshVolumeIndices again;
    tbb::task_arena(threads).execute([&] { mesh_volume_indices(torus, light, facing, again); });
    EXPECT_TRUE(std::equal(again.buffer.begin(), again.buffer.begin() + again.count, volume.buffer.begin())) << threads;
  }
  EXPECT_TRUE(has_no_boundary(mesh_shadow_volume(torus, light)));
}

TEST(MeshVolume, EveryBundledClosedMeshGivesVolumesWithoutBoundaryForManyLights) {
  int meshes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes")) {
    if (mesh_format_of(entry.path().string()).empty()) continue;
    const MeshAnalysis a = analyse_mesh(read_polygon_soup(entry.path().string()));
    if (!a.report.topology_problems().empty()) continue;
    ++meshes;
    const MeshAdjacency mesh = build_mesh_adjacency(a.positions, a.triangles);
    for (const glm::dvec3& light : lights_around(100, 6)) {
      const ShadowVolume v = mesh_shadow_volume(mesh, light);
      EXPECT_TRUE(has_no_boundary(v)) << entry.path() << ", light " << light.x << " " << light.y << " " << light.z;
    }
  }
  EXPECT_EQ(meshes, 3) << "icosphere.obj, torus.obj and pair.off are closed";
}

TEST(MeshVolume, HasNoBoundaryCatchesAMissingQuad) {
  ShadowVolume v = mesh_shadow_volume(adjacency_of(kCube), {0, 0, 5});
  ASSERT_TRUE(has_no_boundary(v));
  v.triangles.pop_back();
  EXPECT_FALSE(has_no_boundary(v));
}

}  // namespace
}  // namespace umbra
