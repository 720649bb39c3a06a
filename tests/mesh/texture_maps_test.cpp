// Texture maps as the readers take them: OBJ's map_Kd with its faces' `vt`
// (v turned to run down the image), glTF's baseColorTexture with TEXCOORD_0,
// and every way a map can fail to load said once, the mesh still read.
#include <gtest/gtest.h>

#include "image/image.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mesh_file.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

class TextureMapReading : public test::ScratchFolder {
 protected:
  // A 2 x 1 PNG: red, then blue.
  std::string write_png_map(const std::string& name) const {
    Image image(2, 1, 3);
    image.at(0, 0, 0) = 255;
    image.at(1, 0, 2) = 255;
    const std::string path = (folder_ / name).string();
    write_png(image, path);
    return path;
  }
  static const std::string kTriangleWithUvs;
};

const std::string TextureMapReading::kTriangleWithUvs =
    "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.75\nvt 1 1\nvt 0 0\nusemtl painted\nf 1/1 2/-2 3/-1/1\n";

TEST_F(TextureMapReading, ObjCornersTakeTheirVtWithVTurnedOver) {
  write_png_map("red blue.png");
  write("m.mtl", "newmtl painted\nKd 1 1 1\nmap_Kd red blue.png\n");
  const PolygonSoup soup = read_polygon_soup(write("t.obj", kTriangleWithUvs));
  EXPECT_TRUE(soup.warnings.empty()) << soup.warnings[0].message;
  ASSERT_EQ(soup.materials.size(), 1u);
  ASSERT_TRUE(soup.materials[0].texture);
  EXPECT_EQ(soup.materials[0].texture->width, 2);
  EXPECT_EQ(soup.materials[0].texture->height, 1);
  EXPECT_EQ(soup.materials[0].texture->rgba, (std::vector<uint8_t>{255, 0, 0, 255, 0, 0, 255, 255}));
  // vt 1, then vt -2 (the second of three), then vt -1 (the third).
  EXPECT_EQ(soup.corner_uvs, (std::vector<glm::vec2>{{0.25f, 0.25f}, {1.0f, 0.0f}, {0.0f, 1.0f}}));
}

TEST_F(TextureMapReading, MapOptionsAndWindowsSeparatorsStillFindTheFile) {
  write_png_map("wood.png");
  write("m.mtl", "newmtl painted\nmap_Kd -s 1 1 1 -o 0 0 0 .\\wood.png\n");
  const PolygonSoup soup = read_polygon_soup(write("t.obj", kTriangleWithUvs));
  EXPECT_TRUE(soup.warnings.empty()) << soup.warnings[0].message;
  ASSERT_TRUE(soup.materials[0].texture);
}

TEST_F(TextureMapReading, AMapThatCannotBeReadIsSaidOnceAndTheMeshStillLoads) {
  write("broken.png", "not an image at all");
  write("m.mtl", "newmtl painted\nKd 0.5 0.5 0.5\nmap_Kd broken.png\nmap_Bump bumps.png\nmap_Ks shine.png\n");
  const PolygonSoup soup = read_polygon_soup(write("t.obj", kTriangleWithUvs));
  ASSERT_EQ(soup.warnings.size(), 2u);
  EXPECT_EQ(soup.warnings[0].message, "material \"painted\"'s texture map \"" + (folder_ / "broken.png").string() +
                                          "\": cannot decode the image (unknown image type): its faces take the material's Kd colour");
  EXPECT_EQ(soup.warnings[1].message, "the materials' texture maps other than map_Kd (map_Bump and the like) are not drawn");
  EXPECT_FALSE(soup.materials[0].texture);
  EXPECT_TRUE(soup.corner_uvs.empty());  // nothing to look up
  EXPECT_EQ(soup.polygon_count(), 1u);
}

// A check draws nothing: it reads no maps, so a missing one is no warning
// there and costs no decoding.
TEST_F(TextureMapReading, ACheckSkipsTheMaps) {
  write("m.mtl", "newmtl painted\nmap_Kd missing.png\n");
  const PolygonSoup obj = read_polygon_soup(write("t.obj", kTriangleWithUvs), TextureMaps::kSkip);
  EXPECT_TRUE(obj.warnings.empty()) << obj.warnings[0].message;
  EXPECT_FALSE(obj.materials[0].texture);
  EXPECT_TRUE(obj.corner_uvs.empty());
  const PolygonSoup gltf = read_polygon_soup("/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", TextureMaps::kSkip);
  EXPECT_FALSE(gltf.materials[0].texture);
  EXPECT_TRUE(gltf.corner_uvs.empty());
}

TEST_F(TextureMapReading, AVtPastTheLastIsSaidAndTakesZero) {
  write_png_map("red blue.png");
  write("m.mtl", "newmtl painted\nmap_Kd red blue.png\n");
  const PolygonSoup soup = read_polygon_soup(write("t.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nusemtl painted\nf 1/1 2/9 3\n"));
  ASSERT_EQ(soup.warnings.size(), 1u);
  EXPECT_EQ(soup.warnings[0].message, "1 face corners name a texture coordinate past the file's last (vt 9 of 1, the first): they take (0, 0)");
  EXPECT_EQ(soup.corner_uvs, (std::vector<glm::vec2>{{0.5f, 0.5f}, {0.0f, 0.0f}, {0.0f, 0.0f}}));
}

// Texture coordinates are no reason to refuse a mesh that loaded before
// they were read: what cannot be read is said once and takes (0, 0).
TEST_F(TextureMapReading, UnreadableTextureCoordinatesAreSaidOnceAndTakeZero) {
  write_png_map("red blue.png");
  write("m.mtl", "newmtl painted\nmap_Kd red blue.png\n");
  const PolygonSoup soup = read_polygon_soup(
      write("t.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0,5 0,5\nvt 1 1\nusemtl painted\nf 1/1 2/x 3/-5\nf 1/2 2/2 3/2\n"));
  ASSERT_EQ(soup.warnings.size(), 1u);
  EXPECT_EQ(soup.warnings[0].message,
            "3 texture coordinates (vt) or corners' indices of them could not be read, the first at line 5: expected a number for "
            "the texture coordinate u, got \"0,5\": they take (0, 0)");
  EXPECT_EQ(soup.polygon_count(), 2u);
  EXPECT_EQ(soup.corner_uvs, (std::vector<glm::vec2>{{0, 0}, {0, 0}, {0, 0}, {1, 0}, {1, 0}, {1, 0}}));
}

// Khronos's textured box, as .gltf with a PNG beside it, as GLB, and with
// everything embedded as data URIs (Debian's assimp-testmodels).
TEST(TextureMapsInGltf, TheTexturedBoxReadsAlikeInEachPackaging) {
  const std::string models = "/usr/share/assimp/models/glTF2/";
  std::vector<PolygonSoup> soups;
  for (const char* file : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                           "BoxTextured-glTF-Embedded/BoxTextured.gltf"})
    soups.push_back(read_polygon_soup(models + file));
  for (const PolygonSoup& soup : soups) {
    SCOPED_TRACE(soup.path);
    EXPECT_TRUE(soup.warnings.empty()) << soup.warnings[0].message;
    ASSERT_EQ(soup.materials.size(), 1u);
    ASSERT_TRUE(soup.materials[0].texture);
    EXPECT_EQ(soup.materials[0].texture->width, 211);  // CesiumLogoFlat.png
    EXPECT_EQ(soup.materials[0].texture->height, 211);
    // The .gltf's sampler has wrapS 33648 and wrapT 33071; the others' 10497 (repeat) both ways.
    const bool own_sampler = &soup == &soups[0];
    EXPECT_EQ(soup.materials[0].texture->wrap_u, own_sampler ? TextureImage::Wrap::kMirroredRepeat : TextureImage::Wrap::kRepeat);
    EXPECT_EQ(soup.materials[0].texture->wrap_v, own_sampler ? TextureImage::Wrap::kClampToEdge : TextureImage::Wrap::kRepeat);
    EXPECT_EQ(soup.corner_uvs.size(), soup.corners.size());
    EXPECT_EQ(soup.corner_uvs, soups[0].corner_uvs);
    EXPECT_EQ(soup.materials[0].texture->rgba, soups[0].materials[0].texture->rgba);
  }
  EXPECT_EQ(soups[0].corners.size(), 36u);
}

TEST_F(TextureMapReading, AGltfWhoseImageIsMissingStillLoadsAndSaysSo) {
  const std::string box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/";
  for (const char* file : {"BoxTextured.gltf", "BoxTextured0.bin"})
    std::filesystem::copy_file(box + file, folder_ / file);  // not CesiumLogoFlat.png
  const PolygonSoup soup = read_polygon_soup((folder_ / "BoxTextured.gltf").string());
  ASSERT_EQ(soup.warnings.size(), 1u);
  EXPECT_EQ(soup.warnings[0].message,
            "material \"Texture\"'s base colour texture (CesiumLogoFlat.png) could not be read: its faces take the base colour");
  EXPECT_FALSE(soup.materials[0].texture);
  EXPECT_TRUE(soup.corner_uvs.empty());
  EXPECT_EQ(soup.polygon_count(), 12u);
}

}  // namespace
}  // namespace umbra
