// The repair keeps the file's look: each face's material, each corner's
// texture coordinates and shading normal, each point's colour, in the
// formats that can hold them, and says what the others leave out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "image/image.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mesh/check/mesh_repair.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/io/texture_file.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

// A unit cube of quads: colour = position; every quad with its own texture
// coordinates (u from its index, v from the corner) and its outward normal;
// the top (+y) in material "lid", with a map, the rest in "body". The -x
// side is missing (a square hole), and the +z side is wound inward while its
// normal points out, as an exporter's stray face may be.
const std::string kCubeObj = R"(mtllib cube.mtl
v 0 0 0 0 0 0
v 1 0 0 1 0 0
v 1 1 0 1 1 0
v 0 1 0 0 1 0
v 0 0 1 0 0 1
v 1 0 1 1 0 1
v 1 1 1 1 1 1
v 0 1 1 0 1 1
vn 0 -1 0
vn 0 1 0
vn 0 0 -1
vn 0 0 1
vn 1 0 0
usemtl body
vt 0.0 0.0
vt 0.1 0.0
vt 0.1 0.5
vt 0.0 0.5
f 1/1/1 2/2/1 6/3/1 5/4/1
vt 0.2 0.0
vt 0.3 0.0
vt 0.3 0.5
vt 0.2 0.5
f 1/5/3 4/6/3 3/7/3 2/8/3
vt 0.4 0.0
vt 0.5 0.0
vt 0.5 0.5
vt 0.4 0.5
f 5/9/4 8/10/4 7/11/4 6/12/4
vt 0.6 0.0
vt 0.7 0.0
vt 0.7 0.5
vt 0.6 0.5
f 2/13/5 3/14/5 7/15/5 6/16/5
usemtl lid
vt 0.8 0.0
vt 0.9 0.0
vt 0.9 0.5
vt 0.8 0.5
f 4/17/2 8/18/2 7/19/2 3/20/2
)";

const std::string kCubeMtl = "newmtl body\nKd 0 0 1\nnewmtl lid\nKd 1 0.5 0\nNs 10\nKs 0.25 0.25 0.25\nmap_Kd lid.png\n";

class RepairAttributes : public test::ScratchFolder {
 protected:
  void SetUp() override {
    ScratchFolder::SetUp();
    Image map(2, 1, 3);
    map.at(0, 0, 0) = 255;
    map.at(1, 0, 1) = 255;
    write_png(map, (folder_ / "lid.png").string());
    write("cube.mtl", kCubeMtl);
    input_ = read_polygon_soup(write("cube.obj", kCubeObj));
    ASSERT_TRUE(input_.warnings.empty()) << input_.warnings[0].message;
  }

  // Repairs the cube into `name` in the folder; the summary.
  RepairSummary repair(const std::string& name) const {
    const std::string path = (folder_ / name).string();
    return repair_mesh(input_, path, path);
  }

  // The input's corner at `position` on the face whose points all have
  // `axis` at `value`: its texture coordinates and normal.
  struct Corner {
    glm::vec2 uv;
    glm::vec3 normal;
    int material;
  };
  bool input_corner(int axis, double value, const glm::dvec3& position, Corner& corner) const {
    for (size_t f = 0; f < input_.polygon_count(); ++f) {
      bool on = true;
      for (uint32_t k = 0; k < input_.corner_count(f); ++k) on = on && input_.points[input_.polygon(f)[k]][axis] == value;
      if (!on) continue;
      for (uint32_t k = 0; k < input_.corner_count(f); ++k)
        if (input_.points[input_.polygon(f)[k]] == position) {
          const size_t c = input_.polygon_starts[f] + k;
          corner = {input_.corner_uvs[c], input_.corner_normals[c], input_.polygon_material(f)};
          return true;
        }
    }
    return false;
  }

  PolygonSoup input_;
};

TEST_F(RepairAttributes, AnObjKeepsEachFacesMaterialCoordinatesNormalsAndColours) {
  const RepairSummary summary = repair("out.obj");
  ASSERT_EQ(summary.companions.size(), 1u);  // the library; the map is in the output's folder already
  EXPECT_EQ(summary.companions[0].path, (folder_ / "out.mtl").string());
  write("out.mtl", summary.companions[0].bytes);
  const PolygonSoup out = read_polygon_soup((folder_ / "out.obj").string());
  ASSERT_TRUE(out.warnings.empty()) << out.warnings[0].message;

  ASSERT_EQ(out.materials.size(), 2u);
  EXPECT_EQ(out.materials[0].name, "body");
  EXPECT_EQ(out.materials[0].diffuse, glm::dvec3(0, 0, 1));
  EXPECT_EQ(out.materials[1].name, "lid");
  EXPECT_EQ(out.materials[1].diffuse, glm::dvec3(1, 0.5, 0));
  EXPECT_EQ(out.materials[1].specular, glm::dvec3(0.25));
  EXPECT_EQ(out.materials[1].shininess, 10.0);
  ASSERT_TRUE(out.materials[1].texture);
  EXPECT_EQ(out.materials[1].texture->rgba, (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255}));

  // Closed: the hole filled with 2 triangles, the 5 quads split in 2 each.
  ASSERT_EQ(out.polygon_count(), 12u);
  EXPECT_TRUE(check_mesh(out).is_solid());
  ASSERT_EQ(out.point_colors.size(), out.points.size());
  for (size_t p = 0; p < out.points.size(); ++p) EXPECT_EQ(glm::dvec3(out.point_colors[p]), out.points[p]) << p;

  size_t kept = 0, patched = 0;
  for (size_t f = 0; f < out.polygon_count(); ++f) {
    ASSERT_EQ(out.corner_count(f), 3u);
    int axis = -1;
    double value = 0;
    for (int a = 0; a < 3; ++a) {
      const double x = out.points[out.polygon(f)[0]][a];
      if (out.points[out.polygon(f)[1]][a] == x && out.points[out.polygon(f)[2]][a] == x) axis = a, value = x;
    }
    ASSERT_NE(axis, -1) << "face " << f << " lies on no side of the cube";
    const size_t c0 = out.polygon_starts[f];
    if (axis == 0 && value == 0.0) {
      // The hole's patch: a material of the faces round it, the coordinates
      // of one of the input's corners at each point, and no normals (flat).
      ++patched;
      EXPECT_NE(out.polygon_material(f), -1);
      for (uint32_t k = 0; k < 3; ++k) EXPECT_EQ(out.corner_normals[c0 + k], glm::vec3(0.0f));
      continue;
    }
    ++kept;
    for (uint32_t k = 0; k < 3; ++k) {
      Corner corner;
      ASSERT_TRUE(input_corner(axis, value, out.points[out.polygon(f)[k]], corner));
      EXPECT_EQ(out.materials[size_t(out.polygon_material(f))].name, input_.materials[size_t(corner.material)].name) << f;
      EXPECT_EQ(out.corner_uvs[c0 + k], corner.uv) << "face " << f << " corner " << k;
      EXPECT_EQ(out.corner_normals[c0 + k], corner.normal) << "face " << f << " corner " << k;
    }
  }
  EXPECT_EQ(kept, 10u);
  EXPECT_EQ(patched, 2u);
}

TEST_F(RepairAttributes, ANormalTurnsWithTheFaceTheRepairTurnsOutward) {
  // The whole cube wound inward, with normals that agree (pointing in): the
  // repair turns it outward, and the normals with it.
  const std::string inward =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "vn 0 1 0\nvn 0 -1 0\nvn 0 0 1\nvn 0 0 -1\nvn -1 0 0\nvn 1 0 0\n"
      "f 5//1 6//1 2//1 1//1\nf 2//3 3//3 4//3 1//3\nf 5//4 8//4 7//4 6//4\nf 6//5 7//5 3//5 2//5\nf 3//2 7//2 8//2 4//2\n"
      "f 1//6 4//6 8//6 5//6\n";
  const PolygonSoup soup = read_polygon_soup(write("inward.obj", inward));
  const std::string path = (folder_ / "out.obj").string();
  const RepairSummary summary = repair_mesh(soup, path, path);
  ASSERT_NE(std::find(summary.changes.begin(), summary.changes.end(), "turned 1 closed component outward"), summary.changes.end());
  const PolygonSoup out = read_polygon_soup(path);
  ASSERT_EQ(out.corner_normals.size(), out.corners.size());
  for (size_t f = 0; f < out.polygon_count(); ++f) {
    const glm::dvec3 a = out.points[out.polygon(f)[0]], b = out.points[out.polygon(f)[1]], c = out.points[out.polygon(f)[2]];
    const glm::dvec3 centre = (a + b + c) / 3.0;
    const glm::vec3 outward(glm::normalize(glm::cross(b - a, c - a)));
    EXPECT_GT(glm::dot(glm::dvec3(outward), centre - glm::dvec3(0.5)), 0.0) << f;
    for (uint32_t k = 0; k < 3; ++k) EXPECT_EQ(out.corner_normals[out.polygon_starts[f] + k], outward) << f;
  }
}

// Two cubes that overlap, mapped by texture coordinates (x, y) at every
// corner: the repair cuts their faces where they cross and keeps the outer
// pieces, and each piece's corners, the new points on the crossing
// included, take the coordinates interpolated there, which are again (x, y).
TEST_F(RepairAttributes, FacesCutWhereOverlappingPartsMeetTakeTheirCoordinatesInterpolated) {
  std::string obj = "mtllib cube.mtl\nusemtl lid\n";
  for (const double at : {0.0, 0.5}) {
    for (int i = 0; i < 8; ++i) {
      const glm::dvec3 p(at + (i & 1), at + ((i & 2) >> 1), at + ((i & 4) >> 2));
      obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\nvt " + std::to_string(p.x) + " " +
             std::to_string(p.y) + "\n";
    }
    const int base = at == 0.0 ? 1 : 9;
    for (const std::array<int, 4>& quad : std::vector<std::array<int, 4>>{{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}) {
      obj += "f";
      for (const int k : quad) obj += " " + std::to_string(base + k) + "/" + std::to_string(base + k);
      obj += "\n";
    }
  }
  const PolygonSoup soup = read_polygon_soup(write("two.obj", obj));
  const std::string path = (folder_ / "out.obj").string();
  const RepairSummary summary = repair_mesh(soup, path, path);
  ASSERT_TRUE(std::any_of(summary.changes.begin(), summary.changes.end(),
                          [](const std::string& c) { return c.find("pairs of triangles that cross: the parts that overlapped are one surface") != std::string::npos; }))
      << summary.changes.back();
  for (const CompanionFile& companion : summary.companions) write(std::filesystem::path(companion.path).filename(), companion.bytes);
  const PolygonSoup out = read_polygon_soup(path);
  EXPECT_NEAR(test::signed_volume(out, glm::dvec3(0.75)), 2.0 - 0.125, 1e-12);
  ASSERT_EQ(out.corner_uvs.size(), out.corners.size());
  size_t new_points = 0;
  for (size_t c = 0; c < out.corners.size(); ++c) {
    const glm::dvec3 p = out.points[out.corners[c]];
    new_points += std::fmod(p.x, 0.5) != 0.0 || std::fmod(p.y, 0.5) != 0.0 || std::fmod(p.z, 0.5) != 0.0;
    EXPECT_NEAR(out.corner_uvs[c].x, p.x, 1e-6) << "corner " << c;
    EXPECT_NEAR(out.corner_uvs[c].y, 1.0 - p.y, 1e-6) << "corner " << c;
  }
  EXPECT_EQ(new_points, 0u);  // the crossings of these cubes meet at points of the half grid
  for (size_t f = 0; f < out.polygon_count(); ++f) EXPECT_EQ(out.polygon_material(f), 1) << f;
}

TEST_F(RepairAttributes, APlyKeepsColoursAndEachFormatSaysWhatItLeavesOut) {
  const RepairSummary ply = repair("out.ply");
  EXPECT_EQ(ply.changes.back(),
            "left out the materials, texture coordinates and shading normals, which PLY cannot keep (OBJ keeps them all)");
  const PolygonSoup out = read_polygon_soup((folder_ / "out.ply").string());
  ASSERT_EQ(out.point_colors.size(), out.points.size());
  for (size_t p = 0; p < out.points.size(); ++p) EXPECT_EQ(glm::dvec3(out.point_colors[p]), out.points[p]) << p;
  EXPECT_EQ(repair("out.stl").changes.back(),
            "left out the materials, texture coordinates, vertex colours and shading normals, which STL cannot keep (OBJ keeps them "
            "all)");
  EXPECT_EQ(repair("out.off").changes.back(),
            "left out the materials, texture coordinates, vertex colours and shading normals, which OFF cannot keep (OBJ keeps them "
            "all)");
  for (const std::string& change : repair("out.obj").changes) EXPECT_EQ(change.find("left out"), std::string::npos) << change;
}

TEST_F(RepairAttributes, AMapOutsideTheOutputsFolderIsCopiedBesideIt) {
  std::filesystem::create_directory(folder_ / "fixed");
  const std::string path = (folder_ / "fixed" / "out.obj").string();
  const RepairSummary summary = repair_mesh(input_, path, path);
  ASSERT_EQ(summary.companions.size(), 2u);
  EXPECT_EQ(summary.companions[0].path, (folder_ / "fixed" / "out.lid.png").string());
  EXPECT_EQ(summary.companions[0].what, "material \"lid\"'s texture map");
  std::ifstream map((folder_ / "lid.png").string(), std::ios::binary);
  EXPECT_EQ(summary.companions[0].bytes, std::string(std::istreambuf_iterator<char>(map), {}));
  EXPECT_NE(summary.companions[1].bytes.find("\nmap_Kd out.lid.png\n"), std::string::npos) << summary.companions[1].bytes;
}

// Two maps of one name from two folders are two copies; a map that two
// materials name is one.
TEST_F(RepairAttributes, MapsOfOneNameFromTwoFoldersAreCopiedApartAndASharedOneOnce) {
  for (const char* folder : {"a", "b"}) {
    std::filesystem::create_directory(folder_ / folder);
    Image map(1, 1, 3);
    map.at(0, 0, folder[0] == 'a' ? 0 : 2) = 255;
    write_png(map, (folder_ / folder / "wood.png").string());
  }
  write("three.mtl", "newmtl first\nmap_Kd a/wood.png\nnewmtl second\nmap_Kd b/wood.png\nnewmtl third\nmap_Kd a/wood.png\n");
  const PolygonSoup soup = read_polygon_soup(write("three.obj", "mtllib three.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\n"
                                                                "usemtl first\nf 1/1 3/1 2/1\nusemtl second\nf 1/1 2/1 4/1\n"
                                                                "usemtl third\nf 2/1 3/1 4/1\nf 1/1 4/1 3/1\n"));
  ASSERT_TRUE(soup.warnings.empty()) << soup.warnings[0].message;
  std::filesystem::create_directory(folder_ / "out");
  const std::string path = (folder_ / "out" / "x.obj").string();
  const RepairSummary summary = repair_mesh(soup, path, path);
  ASSERT_EQ(summary.companions.size(), 3u);  // two maps and the library
  EXPECT_EQ(summary.companions[0].path, (folder_ / "out" / "x.wood.png").string());
  EXPECT_EQ(summary.companions[1].path, (folder_ / "out" / "x.1.wood.png").string());
  EXPECT_NE(summary.companions[0].bytes, summary.companions[1].bytes);
  EXPECT_NE(summary.companions[2].bytes.find("newmtl third\nKd 0.8 0.8 0.8\nKs 0 0 0\nNs 32\nmap_Kd x.wood.png\n"), std::string::npos)
      << summary.companions[2].bytes;
  for (const CompanionFile& companion : summary.companions) write("out/" + std::filesystem::path(companion.path).filename().string(), companion.bytes);
  const PolygonSoup out = read_polygon_soup(path);
  ASSERT_EQ(out.materials.size(), 3u);
  EXPECT_EQ(out.materials[0].texture->rgba, (std::vector<uint8_t>{255, 0, 0, 255}));
  EXPECT_EQ(out.materials[1].texture->rgba, (std::vector<uint8_t>{0, 0, 255, 255}));
  EXPECT_EQ(out.materials[2].texture->rgba, (std::vector<uint8_t>{255, 0, 0, 255}));
}

TEST_F(RepairAttributes, AMapHeldInsideAGlbIsWrittenBesideTheObjAsPng) {
  const std::string glb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  if (!std::filesystem::exists(glb)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const PolygonSoup soup = read_polygon_soup(glb);
  ASSERT_EQ(soup.materials.size(), 1u);
  ASSERT_TRUE(soup.materials[0].texture);
  const std::string path = (folder_ / "box.obj").string();
  const RepairSummary summary = repair_mesh(soup, path, path);
  ASSERT_EQ(summary.companions.size(), 2u);
  EXPECT_EQ(summary.companions[0].path, (folder_ / "box.0.png").string());
  std::string error;
  const auto written = decode_texture(summary.companions[0].bytes, "box.0.png", error);
  ASSERT_TRUE(written) << error;
  EXPECT_EQ(written->width, soup.materials[0].texture->width);
  EXPECT_EQ(written->rgba, soup.materials[0].texture->rgba);
  for (const CompanionFile& companion : summary.companions) write(std::filesystem::path(companion.path).filename(), companion.bytes);
  const PolygonSoup out = read_polygon_soup(path);
  ASSERT_TRUE(out.warnings.empty()) << out.warnings[0].message;
  ASSERT_TRUE(out.materials.at(0).texture);
  EXPECT_EQ(out.materials[0].texture->rgba, soup.materials[0].texture->rgba);
}

// A glTF sampler's clamp-to-edge, written as MTL's -clamp on and read back
// so: --repair to .obj once dropped it, and its map repeated.
TEST_F(RepairAttributes, AClampedMapStaysClampedInTheObj) {
  const std::string glb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  if (!std::filesystem::exists(glb)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  PolygonSoup soup = read_polygon_soup(glb);
  ASSERT_TRUE(soup.materials.at(0).texture);
  auto clamped = std::make_shared<TextureImage>(*soup.materials[0].texture);
  clamped->wrap_u = clamped->wrap_v = TextureImage::Wrap::kClampToEdge;
  soup.materials[0].texture = clamped;
  const std::string path = (folder_ / "box.obj").string();
  const RepairSummary summary = repair_mesh(soup, path, path);
  for (const CompanionFile& companion : summary.companions) write(std::filesystem::path(companion.path).filename(), companion.bytes);
  EXPECT_NE(summary.companions.back().bytes.find("map_Kd -clamp on box.0.png\n"), std::string::npos) << summary.companions.back().bytes;
  const PolygonSoup out = read_polygon_soup(path);
  ASSERT_TRUE(out.warnings.empty()) << out.warnings[0].message;
  ASSERT_TRUE(out.materials.at(0).texture);
  EXPECT_EQ(out.materials[0].texture->wrap_u, TextureImage::Wrap::kClampToEdge);
  EXPECT_EQ(out.materials[0].texture->wrap_v, TextureImage::Wrap::kClampToEdge);
}

}  // namespace
}  // namespace umbra
