// glTF, GLB and 3MF files as the project writes them (interchange_writers.hpp):
// the same verdicts as the equivalent OBJ, node and build transforms, the
// files' materials, format detection without extensions, and the exact
// message for each kind of broken file.
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "mesh/io/mesh_format.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mesh_file.hpp"
#include "tests/mesh/read_error.hpp"
#include "tests/mesh/interchange_writers.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

using test::GltfOptions;


std::string gltf_of(const PolygonSoup& soup, const GltfOptions& options = {}) {
  return test::gltf_json(soup, test::gltf_buffer(soup), options);
}

std::string glb_of(const PolygonSoup& soup, const GltfOptions& options = {}) {
  const std::string buffer = test::gltf_buffer(soup);
  return test::glb(test::gltf_json(soup, buffer, options, true), buffer);
}

const std::string kBlue = R"(<basematerials id="1"><base name="blue" displaycolor="#0000FF"/><base name="grey" displaycolor="#808080"/></basematerials>)";

std::string threemf_of(const PolygonSoup& soup, const std::string& transform = "", int pindex = -1) {
  return test::threemf(kBlue + test::threemf_object(2, soup, pindex),
                       "<item objectid=\"2\"" + (transform.empty() ? "" : " transform=\"" + transform + "\"") + "/>");
}

// A file's report next to the same mesh's as OBJ: every count and verdict.
void expect_same_report(const MeshReport& a, const MeshReport& b) {
  EXPECT_EQ(a.is_closed_manifold(), b.is_closed_manifold());
  EXPECT_EQ(a.problems(), b.problems());
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.border_edges, b.border_edges);
  EXPECT_EQ(a.border_loops, b.border_loops);
  EXPECT_EQ(a.inconsistent_edges, b.inconsistent_edges);
  EXPECT_EQ(a.inward_components, b.inward_components);
  EXPECT_EQ(a.bbox_min, b.bbox_min);
  EXPECT_EQ(a.bbox_max, b.bbox_max);
}

TEST(InterchangeFormats, SameVerdictsAsTheEquivalentObj) {
  const PolygonSoup closed = test::unit_cube();
  const PolygonSoup open = test::without_faces(closed, {3});
  const PolygonSoup flipped = test::reversed(closed, {0, 5});
  for (const PolygonSoup* soup : {&closed, &open, &flipped}) {
    const MeshReport obj = check_mesh(parse_polygon_soup(test::obj_text(*soup), "m.obj"));
    const MeshReport gltf = check_mesh(parse_polygon_soup(gltf_of(*soup), "m.gltf"));
    const MeshReport glb = check_mesh(parse_polygon_soup(glb_of(*soup), "m.glb"));
    const MeshReport three = check_mesh(parse_polygon_soup(threemf_of(*soup), "m.3mf"));
    EXPECT_EQ(gltf.format, "glTF");
    EXPECT_EQ(glb.format, "glTF (binary .glb)");
    EXPECT_EQ(three.format, "3MF");
    expect_same_report(gltf, obj);
    expect_same_report(glb, obj);
    expect_same_report(three, obj);
  }
  EXPECT_TRUE(check_mesh(parse_polygon_soup(gltf_of(closed), "m.gltf")).is_closed_manifold());
  EXPECT_EQ(check_mesh(parse_polygon_soup(threemf_of(open), "m.3mf")).border_edges, 3u);
}

TEST(InterchangeFormats, GltfNodeTransformsNestAndPlaceTheMesh) {
  const PolygonSoup cube = test::unit_cube();
  const auto bbox = [&](const GltfOptions& o) {
    const MeshReport r = check_mesh(parse_polygon_soup(gltf_of(cube, o), "m.gltf"));
    return std::make_pair(r.bbox_min, r.bbox_max);
  };
  GltfOptions trs;
  trs.node = R"("mesh": 0, "translation": [10, 20, 30], "scale": [2, 3, 4])";
  EXPECT_EQ(bbox(trs), std::make_pair(glm::dvec3(10, 20, 30), glm::dvec3(12, 23, 34)));
  // A quarter turn about z: x -> y, y -> -x (quaternion x y z w).
  GltfOptions turn;
  turn.node = R"("mesh": 0, "rotation": [0, 0, 0.7071067811865476, 0.7071067811865476])";
  const auto [lo, hi] = bbox(turn);
  EXPECT_NEAR(lo.x, -1, 1e-6);
  EXPECT_NEAR(hi.y, 1, 1e-6);
  EXPECT_NEAR(lo.y, 0, 1e-6);
  // A parent's column-major matrix (translate by 5 in x) applies after the child's translation.
  GltfOptions nested;
  nested.node = R"("matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 5,0,0,1], "children": [1])";
  nested.extra_nodes = R"(, {"mesh": 0, "translation": [0, 0, 7]})";
  EXPECT_EQ(bbox(nested), std::make_pair(glm::dvec3(5, 0, 7), glm::dvec3(6, 1, 8)));
}

TEST(InterchangeFormats, MirroringTransformsKeepTheMeshFacingOutward) {
  GltfOptions mirror;
  mirror.node = R"("mesh": 0, "scale": [-1, 1, 1])";
  const MeshReport gltf = check_mesh(parse_polygon_soup(gltf_of(test::unit_cube(), mirror), "m.gltf"));
  EXPECT_TRUE(gltf.is_closed_manifold());
  EXPECT_EQ(gltf.inward_components, 0u);
  EXPECT_EQ(gltf.bbox_min, glm::dvec3(-1, 0, 0));
  const MeshReport three = check_mesh(parse_polygon_soup(threemf_of(test::unit_cube(), "1 0 0 0 1 0 0 0 -1 0 0 0"), "m.3mf"));
  EXPECT_EQ(three.inward_components, 0u);
  EXPECT_EQ(three.bbox_min, glm::dvec3(0, 0, -1));
}

TEST(InterchangeFormats, GltfStripsAndFansBecomeTriangles) {
  // Four points of a unit square: as a strip 0 1 2 3 and as a fan 0 1 2 3.
  PolygonSoup square = test::make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2, 3}});
  GltfOptions strip;
  strip.mode = 5;
  const PolygonSoup s = parse_polygon_soup(gltf_of(square, strip), "m.gltf");
  ASSERT_EQ(s.polygon_count(), 2u);
  EXPECT_EQ(std::vector<uint32_t>(s.corners.begin(), s.corners.end()), (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));
  GltfOptions fan;
  fan.mode = 6;
  const PolygonSoup f = parse_polygon_soup(gltf_of(square, fan), "m.gltf");
  EXPECT_EQ(std::vector<uint32_t>(f.corners.begin(), f.corners.end()), (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  GltfOptions lines;
  lines.mode = 1;
  const PolygonSoup l = parse_polygon_soup(gltf_of(square, lines), "m.gltf");
  EXPECT_EQ(l.polygon_count(), 0u);
  ASSERT_EQ(l.warnings.size(), 1u);
  EXPECT_EQ(l.warnings[0].message, "mesh 0 primitive 0 is made of points or lines: skipped");
}

// Mesh optimisers (gltfpack) store positions as integers (KHR_mesh_quantization):
// here the unit cube's corners as normalised unsigned shorts, 8 bytes apart.
TEST(InterchangeFormats, GltfQuantisedPositionsAreRead) {
  const PolygonSoup cube = test::unit_cube();
  std::string buffer;
  for (const glm::dvec3& p : cube.points)
    for (const double c : {p.x, p.y, p.z, 0.0}) test::append_le(buffer, uint16_t(c * 65535));
  const size_t point_bytes = buffer.size();
  for (uint32_t c : cube.corners) test::append_le(buffer, c);
  const std::string json =
      R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],)"
      R"( "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "scale": [2, 2, 2]}],)"
      R"( "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}], "buffers": [{"byteLength": )" +
      std::to_string(buffer.size()) + R"(}], "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" +
      std::to_string(point_bytes) + R"(, "byteStride": 8}, {"buffer": 0, "byteOffset": )" + std::to_string(point_bytes) +
      R"(, "byteLength": )" + std::to_string(buffer.size() - point_bytes) +
      R"(}], "accessors": [{"bufferView": 0, "componentType": 5123, "normalized": true, "count": 8, "type": "VEC3"},)"
      R"( {"bufferView": 1, "componentType": 5125, "count": 36, "type": "SCALAR"}]})";
  const MeshReport r = check_mesh(parse_polygon_soup(test::glb(json, buffer), "q.glb"));
  EXPECT_TRUE(r.is_closed_manifold());
  EXPECT_EQ(r.bbox_min, glm::dvec3(0.0));
  EXPECT_EQ(r.bbox_max, glm::dvec3(2.0));
}

TEST(InterchangeFormats, ThreeMfBuildAndComponentTransformsCompose) {
  const std::string resources = kBlue + test::threemf_object(2, test::unit_cube()) +
                                R"(<object id="3" type="model"><components><component objectid="2" transform="2 0 0 0 2 0 0 0 2 0 0 0"/>)"
                                R"(</components></object>)";
  const MeshReport r = check_mesh(parse_polygon_soup(test::threemf(resources, R"(<item objectid="3" transform="1 0 0 0 1 0 0 0 1 10 20 30"/>)"), "m.3mf"));
  EXPECT_EQ(r.bbox_min, glm::dvec3(10, 20, 30));
  EXPECT_EQ(r.bbox_max, glm::dvec3(12, 22, 32));
  EXPECT_TRUE(r.is_closed_manifold());
}

TEST(InterchangeFormats, MaterialsComeWithTheirFaces) {
  const PolygonSoup gltf = parse_polygon_soup(gltf_of(test::unit_cube()), "m.gltf");
  ASSERT_EQ(gltf.materials.size(), 1u);
  EXPECT_EQ(gltf.materials[0].name, "red");
  EXPECT_EQ(gltf.materials[0].diffuse, glm::dvec3(1, 0, 0));
  EXPECT_EQ(gltf.polygon_materials, std::vector<int>(12, 0));
  const PolygonSoup three = parse_polygon_soup(threemf_of(test::unit_cube(), "", 1), "m.3mf");
  ASSERT_EQ(three.materials.size(), 1u);  // only the base material in use
  EXPECT_EQ(three.materials[0].name, "grey");
  EXPECT_EQ(three.materials[0].diffuse, glm::dvec3(128.0 / 255.0));
  EXPECT_EQ(three.polygon_materials, std::vector<int>(12, 0));
  const PolygonSoup plain = parse_polygon_soup(threemf_of(test::unit_cube()), "m.3mf");
  EXPECT_EQ(plain.polygon_materials, std::vector<int>(12, -1));
}

TEST(InterchangeFormats, FoundByContentWhateverTheName) {
  const PolygonSoup cube = test::unit_cube();
  EXPECT_EQ(parse_polygon_soup(gltf_of(cube), "model").format, "glTF");
  EXPECT_EQ(parse_polygon_soup(glb_of(cube), "model.bin").format, "glTF (binary .glb)");
  EXPECT_EQ(parse_polygon_soup(threemf_of(cube), "model.zip").format, "3MF");
  EXPECT_EQ(parse_polygon_soup(gltf_of(cube), "model.obj").format, "glTF");
  EXPECT_EQ(parse_polygon_soup(test::obj_text(cube), "model.stl").format, "OBJ");
}

// (Prose, UTF-16 and images: mesh_file_test.cpp.)
TEST(InterchangeFormats, FilesThatAreNoMeshSayWhatTheyAre) {
  EXPECT_EQ(test::read_error_of(std::string("v 0 0 0\n\x01\x02\x03 binary\n", 20), "odd.obj"),
            "odd.obj: not a mesh file (" + mesh_format_names() + "): binary data");
  EXPECT_EQ(test::read_error_of(test::stored_zip({{"readme.txt", "hello"}}), "archive.3mf"),
            "archive.3mf: not a mesh file (" + mesh_format_names() + "): a zip archive without a 3D model part");
}

// glTF 1.0, as GLB (header version 1) and as JSON (its dictionaries of
// meshes and nodes, where 2.0 has arrays), is Assimp's glTF importer's,
// never read by tinygltf as an empty mesh; what 2.0's schema forbids is
// refused; compressed meshes name their extension.
TEST(InterchangeFormats, GltfOnlyVersionTwoAsItsSchemaHasIt) {
  const auto by_assimp = [](const std::string& error, const std::string& name) {
    const std::string said = name + ": Assimp's glTF Importer cannot read it";
    EXPECT_EQ(error.substr(0, said.size()), said) << error;
  };
  by_assimp(test::read_error_of(R"({"asset": {"version": "1.0"}, "meshes": {"box": {"primitives": []}}, "nodes": {}})", "m.gltf"), "m.gltf");
  by_assimp(test::read_error_of(R"({"asset": {}, "meshes": {"box": {"primitives": []}}})", "m.gltf"), "m.gltf");
  std::string glb1 = "glTF";
  test::append_le(glb1, uint32_t(1));
  test::append_le(glb1, uint32_t(40));
  glb1 += std::string(28, ' ');
  by_assimp(test::read_error_of(glb1, "m.glb"), "m.glb");

  const PolygonSoup cube = test::unit_cube();
  std::string object = gltf_of(cube, {});
  object.replace(object.find(R"("primitives": [)"), 15, R"("primitives": {"0": )");
  object.replace(object.find(R"(}]}], "materials")"), 17, R"(}}}], "materials")");
  EXPECT_EQ(test::read_error_of(object, "m.gltf"), "m.gltf: not a valid glTF 2.0 file: mesh 0's \"primitives\" must be an array");

  // Node 2 under both node 0 and node 1: a graph, not the tree glTF requires.
  GltfOptions shared;
  shared.node = R"("children": [1, 2])";
  shared.extra_nodes = R"(, {"children": [2]}, {"mesh": 0})";
  EXPECT_EQ(test::read_error_of(gltf_of(cube, shared), "m.gltf"),
            "m.gltf: not a valid glTF 2.0 file: node 2 has two parents (nodes 0 and 1); glTF's nodes form trees");

  // A child listed twice: 20 such nodes in a chain are 2^20 paths, a file
  // under 1 KB that would never finish. The schema makes children unique.
  GltfOptions twice;
  twice.node = R"("children": [1, 1])";
  twice.extra_nodes = R"(, {"mesh": 0})";
  EXPECT_EQ(test::read_error_of(gltf_of(cube, twice), "m.gltf"),
            "m.gltf: not a valid glTF 2.0 file: node 0 lists node 1 as its child twice; glTF's nodes form trees");
  GltfOptions chain;
  chain.node = R"("children": [1, 1])";
  for (int n = 1; n < 20; ++n) chain.extra_nodes += ", {\"children\": [" + std::to_string(n + 1) + ", " + std::to_string(n + 1) + "]}";
  chain.extra_nodes += R"(, {"mesh": 0})";
  EXPECT_EQ(test::read_error_of(gltf_of(cube, chain), "m.gltf"),
            "m.gltf: not a valid glTF 2.0 file: node 0 lists node 1 as its child twice; glTF's nodes form trees");
  // A scene that lists a root twice, or a node with a parent as a root.
  GltfOptions root_twice;
  root_twice.scene_nodes = "[0, 0]";
  EXPECT_EQ(test::read_error_of(gltf_of(cube, root_twice), "m.gltf"),
            "m.gltf: not a valid glTF 2.0 file: scene 0 lists node 0 as a root twice; glTF's nodes form trees");

  std::string meshopt = gltf_of(cube, {});
  meshopt.replace(meshopt.find(R"("asset")"), 7, R"("extensionsRequired": ["EXT_meshopt_compression"], "extensionsUsed": ["EXT_meshopt_compression"], "asset")");
  EXPECT_EQ(test::read_error_of(meshopt, "m.gltf"),
            "m.gltf: its meshes are compressed with EXT_meshopt_compression, which umbra does not read (gltfpack writes it with -c "
            "or -cc, and plain meshes without them)");
}

TEST(InterchangeFormats, BrokenFilesGiveTheirExactMessage) {
  const PolygonSoup cube = test::unit_cube();
  std::string buffer = test::gltf_buffer(cube);
  // Index 5 of the index accessor names vertex 99 of 8.
  std::string bad_index = buffer;
  const uint32_t ninety_nine = 99;
  std::memcpy(bad_index.data() + 8 * 12 + 5 * 4, &ninety_nine, 4);
  EXPECT_EQ(test::read_error_of(test::gltf_json(cube, bad_index, {}), "m.gltf"),
            "m.gltf: mesh 0 primitive 0 index 5 is 99, but the primitive has 8 vertices");
  std::string nan = buffer;
  const float not_a_number = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(nan.data() + 3 * 12 + 4, &not_a_number, 4);
  EXPECT_EQ(test::read_error_of(test::gltf_json(cube, nan, {}), "m.gltf"),
            "m.gltf: mesh 0 primitive 0 vertex 3 has a coordinate that is not a finite number");
  GltfOptions cycle;
  cycle.node = R"("children": [1])";
  cycle.extra_nodes = R"(, {"mesh": 0, "children": [0]})";
  EXPECT_EQ(test::read_error_of(gltf_of(cube, cycle), "m.gltf"), "m.gltf: node 0 is its own ancestor: the node hierarchy has a cycle");
  GltfOptions missing;
  missing.buffer_uri = "cube-does-not-exist.bin";
  EXPECT_EQ(test::read_error_of(gltf_of(cube, missing), "/nonexistent/m.gltf"),
            "/nonexistent/m.gltf: not a valid glTF file: File not found : cube-does-not-exist.bin");
  const std::string package = threemf_of(cube);
  EXPECT_EQ(test::read_error_of(package.substr(0, package.size() / 2), "m.3mf"),
            "m.3mf: not a valid 3MF file: the zip archive is cut short (it has no end of central directory)");
  EXPECT_EQ(test::read_error_of("\t", "m.3mf"), "m.3mf: the file holds only blank lines");
  EXPECT_EQ(test::read_error_of("x", "m.3mf"), "m.3mf: not a valid 3MF file: it is not a zip archive, which a 3MF file is");
  const std::string outside = test::threemf(
      R"(<object id="2" type="model"><mesh><vertices><vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/>)"
      R"(<vertex x="0" y="1" z="0"/></vertices><triangles><triangle v1="0" v2="1" v3="7"/></triangles></mesh></object>)",
      R"(<item objectid="2"/>)");
  EXPECT_EQ(test::read_error_of(outside, "m.3mf"), "m.3mf: not a valid 3MF file: Invalid model node index");  // a triangle names vertex 7 of 3
  // lib3mf's warnings, one per element, are said once per kind, counted.
  const PolygonSoup warned = parse_polygon_soup(test::threemf(test::threemf_object(2, cube) + "<unknown/><unknown/><unknown/>",
                                                              R"(<item objectid="2"/>)"),
                                                "w.3mf");
  ASSERT_EQ(warned.warnings.size(), 1u);
  EXPECT_EQ(warned.warnings[0].message, "lib3mf: Invalid Element in namespace. (3 times)");
  // An object with no content, as assimp's exporter writes one: named.
  const std::string hollow = test::threemf(test::threemf_object(2, cube) + R"(<object id="3" type="model" name="Empty"></object>)",
                                           R"(<item objectid="2"/>)");
  EXPECT_EQ(test::read_error_of(hollow, "m.3mf"), "m.3mf: not a valid 3MF file: object 3 (\"Empty\") has neither a mesh nor "
                                                  "components (lib3mf: An object has no supported content type)");
}

}  // namespace
}  // namespace umbra
