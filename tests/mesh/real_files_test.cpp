// Real exported files, as Debian's assimp-testmodels ships them (build.sh
// installs it): the same mesh from four exporters gets one report, exporters'
// quirks are read with their warning, and broken files get their message.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "mesh/check/mesh_check.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/io/mesh_format.hpp"
#include "tests/mesh/triangle_topology_expect.hpp"

namespace umbra {
namespace {

const std::string kModels = "/usr/share/assimp/models/";

class RealFiles : public testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kModels)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  }
  static MeshReport check(const std::string& name) { return check_mesh(read_polygon_soup(kModels + name)); }
  // The message after "PATH".
  static std::string error(const std::string& name) {
    try {
      read_polygon_soup(kModels + name);
    } catch (const InputError& e) {
      return std::string(e.what()).substr(kModels.size() + name.size());
    }
    return "no error";
  }
};

TEST_F(RealFiles, OneModelFromFourExportersGetsOneReport) {
  for (const char* name : {"OBJ/WusonOBJ.obj", "PLY/Wuson.ply", "STL/Wuson.stl", "OFF/Wuson.off"}) {
    const MeshReport r = check(name);
    EXPECT_EQ(r.file_faces, 3732u) << name;
    EXPECT_EQ(r.vertices, 2117u) << name;
    EXPECT_EQ(r.edges, 5804u) << name;
    EXPECT_EQ(r.border_edges, 412u) << name;
    EXPECT_EQ(r.border_loops, 55u) << name;  // loops that touch at a vertex count apart (52 before they did)
    EXPECT_EQ(r.non_manifold_vertices, 6u) << name;
    EXPECT_EQ(r.components.size(), 54u) << name;
    EXPECT_EQ(r.self_intersections.face_pairs, 509u) << name;
  }
}

TEST_F(RealFiles, APolygonWhoseDiagonalRunsAlongAnotherEdgeKeepsItsComponentFromTheSilhouette) {
  // A quad and two triangles that share its diagonal, back to back: closed in
  // the file, but that diagonal has four triangles once the quad is split.
  const MeshReport r = check("OBJ/regr_3429812.obj");
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_TRUE(r.components[0].closed);
  EXPECT_EQ(r.components[0].overlapping_diagonals, 1u);
  EXPECT_FALSE(r.components[0].casts_from_silhouette());
  EXPECT_EQ(r.volume_kind(), VolumeKind::kEdgeMultiplicity);
}

// assimp's glTF 1.0 set, which tinygltf does not read: as JSON and
// embedded, read through Assimp's glTF importer; as binary, which that
// importer takes for none of its own, refused naming it; never an empty mesh.
TEST_F(RealFiles, GltfOneFilesAreReadThroughAssimp) {
  for (const char* name : {"glTF/TwoBoxes/TwoBoxes.gltf", "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf",
                           "glTF/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
    const MeshReport r = check(name);
    EXPECT_EQ(r.format, "read through Assimp's glTF Importer") << name;
    EXPECT_GE(r.triangles, 12u) << name;
  }
  EXPECT_EQ(error("glTF/BoxTextured-glTF-Binary/BoxTextured.glb").substr(0, 41), ": Assimp's glTF Importer cannot read it: ");
}

TEST_F(RealFiles, InterchangeFormatsReadWithTheirVerdicts) {
  const MeshReport box3mf = check("3MF/box.3mf");
  EXPECT_EQ(box3mf.format, "3MF");
  EXPECT_TRUE(box3mf.is_closed_manifold());
  for (const char* name : {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", "glTF2/BoxTextured-glTF/BoxTextured.gltf",
                           "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
    const MeshReport r = check(name);
    EXPECT_EQ(r.file_faces, 12u) << name;
    EXPECT_TRUE(r.is_closed_manifold()) << name;
  }
  const MeshReport engine = check("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  EXPECT_EQ(engine.file_faces, 121496u);
  EXPECT_EQ(engine.components.size(), 96u);
}

// gltfpack (Debian's mesh optimiser for glTF) stores positions as integers
// (KHR_mesh_quantization): its output of the engine is the same engine, to
// within the quantisation step.
TEST_F(RealFiles, GltfpackOutputIsTheSameModel) {
  if (std::system("command -v gltfpack >/dev/null") != 0) GTEST_SKIP() << "needs Debian's gltfpack (build.sh installs it)";
  const std::string engine = "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  const std::string packed = testing::TempDir() + "umbra-engine-packed-" + std::to_string(::getpid()) + ".glb";
  ASSERT_EQ(std::system(("gltfpack -i " + kModels + engine + " -o " + packed + " >/dev/null 2>&1").c_str()), 0);
  const MeshReport original = check(engine);
  const MeshReport r = check_mesh(read_polygon_soup(packed));
  std::filesystem::remove(packed);
  EXPECT_EQ(r.format, "glTF (binary .glb)");
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(r.bbox_min[k], original.bbox_min[k], 0.05) << k;
    EXPECT_NEAR(r.bbox_max[k], original.bbox_max[k], 0.05) << k;
  }
  EXPECT_NEAR(double(r.triangles), double(original.triangles), 0.001 * double(original.triangles));
}

TEST_F(RealFiles, ExportersQuirksAreReadWithAWarning) {
  // Blender 2.47's PLY names its maker in a header line of its own.
  const MeshReport wuson = check("PLY/Wuson.ply");
  ASSERT_EQ(wuson.warnings.size(), 1u);
  EXPECT_EQ(wuson.warnings[0].message, "unknown PLY header line \"Created\" ignored");
  // A 66-corner polygon round a hole, through a bridge it walks twice.
  const MeshReport keyhole = check("OBJ/concave_polygon.obj");
  EXPECT_EQ(keyhole.file_faces, 64u);  // counted as split
  EXPECT_EQ(keyhole.triangles, 64u);
  EXPECT_EQ(keyhole.degenerate_faces, 0u);
  EXPECT_EQ(keyhole.border_loops, 2u);
  EXPECT_EQ(keyhole.self_intersections.face_pairs, 0u);
  ASSERT_EQ(keyhole.warnings.size(), 1u);
  EXPECT_EQ(keyhole.warnings[0].message, "face 0 (66 corners) visits a vertex more than once: read as 64 triangles");
}

TEST_F(RealFiles, BrokenFilesGetTheirMessage) {
  EXPECT_EQ(error("glTF2/IndexOutOfRange/IndexOutOfRange.gltf"), ": mesh 0 primitive 0 index 0 is 255, but the primitive has 24 vertices");
  EXPECT_EQ(error("glTF2/RecursiveNodes/RecursiveNodes.gltf"), ": node 0 is its own ancestor: the node hierarchy has a cycle");
  EXPECT_EQ(error("glTF2/MissingBin/BoxTextured.gltf"), ": not a valid glTF file: File not found : BoxTextured0.bin");
  EXPECT_EQ(error("glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"),
            ": mesh 0 primitive 0 vertex 0 has a coordinate that is not a finite number");
  // Draco-compressed meshes, which tinygltf does not read, are Assimp's glTF2 importer's.
  EXPECT_EQ(check("glTF2/draco/2CylinderEngine.gltf").format, "read through Assimp's glTF2 Importer");
  EXPECT_EQ(error("OBJ/box_UTF16BE.obj"), ": not a mesh file (" + mesh_format_names() + "): UTF-16 text");
}

}  // namespace
}  // namespace umbra

namespace umbra {
namespace {

// Every model in assimp's set that reads as a mesh: the renderer's choice
// per component (the check's, through triangle_topology) is what a pass over
// the triangles alone decides, and its counts are the report's.
TEST(RealFilesAgreement, TheRendererCastsEveryComponentAsTheCheckDecides) {
  if (!std::filesystem::exists(kModels)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  size_t meshes = 0, mixed = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kModels)) {
    // umbra's own readers' files. Through Assimp, IFC's walls
    // (AC14-FZK-Haus.ifc) give the check 4 border edges and loops more than
    // a pass over the bare triangles finds: an open question, not yet
    // explained (bare triangles cannot tell a polygon's diagonal from a
    // file's edge, which the non-manifold count below allows for).
    const std::string format = detect_mesh_format_of_file(entry.path().string());
    if (!entry.is_regular_file() || format.empty() || format == "assimp") continue;
    PolygonSoup soup;
    try {
      soup = read_polygon_soup(entry.path().string());
    } catch (const InputError&) {
      continue;  // broken files have tests of their own
    }
    SCOPED_TRACE(entry.path().string());
    CheckOptions options;
    options.self_intersection_seconds = 0.0;
    options.triangle_topology = true;
    const MeshAnalysis a = analyse_mesh(soup, options);
    const SilhouetteComponents& c = a.topology->components;
    EXPECT_EQ(c.components, a.report.components.size());
    EXPECT_EQ(c.silhouette_components, a.report.silhouette_components());
    EXPECT_EQ(c.border_loops, a.report.border_loops);
    size_t overlapping_diagonals = 0;
    for (const ComponentReport& r : a.report.components) overlapping_diagonals += r.overlapping_diagonals;
    EXPECT_EQ(c.non_manifold_edges, a.report.non_manifold_edges);
    EXPECT_EQ(c.overlapping_diagonals, overlapping_diagonals);
    EXPECT_EQ(c.non_manifold_vertices, a.report.non_manifold_vertices);
    EXPECT_TRUE(test::expect_triangle_topology_as_built(soup));
    ++meshes;
    mixed += a.report.volume_kind() == VolumeKind::kMixed;
  }
  EXPECT_GE(meshes, 77u);  // the rest of the set is in formats umbra does not read, or broken
  EXPECT_GT(mixed, 10u);  // files whose closed and open parts cast each their own way
}

}  // namespace
}  // namespace umbra
