// Texture maps as the readers take them: OBJ's map_Kd with its faces' `vt`
// (v turned to run down the image), glTF's baseColorTexture with TEXCOORD_0,
// and every way a map can fail to load said once, the mesh still read.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>

#include "image/image.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/io/texture_file.hpp"
#include "tests/mesh/interchange_writers.hpp"
#include "tests/mesh/mesh_builders.hpp"
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
    "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.75\nvt 1 1\nvt 0 0\nvn 0 0 1\nusemtl painted\nf 1/1 2/-2 3/-1/1\n";

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

// One model's maps share a budget of decoded pixels (2^28): twelve maps of
// 8192 x 8192 once took 6.5 GB for a small picture. A map past what is
// left is refused from its header, before it is decoded, and said.
TEST_F(TextureMapReading, AModelsMapsShareOneBudgetOfDecodedPixels) {
  TextureBudget budget;
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(budget.take(kMostTexturePixels)) << k;  // four of the largest maps
  EXPECT_FALSE(budget.take(1));
  Image small(4, 4, 3, 90);
  write_png(small, (folder_ / "small.png").string());
  std::vector<unsigned char> bytes;
  std::string error;
  ASSERT_TRUE(read_regular_file((folder_ / "small.png").string(), kMostTextureFileBytes, bytes, error)) << error;
  const std::string_view png(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  TextureBudget nearly_spent;
  ASSERT_TRUE(nearly_spent.take(kMostModelTexturePixels - 15));
  EXPECT_EQ(decode_texture(png, "small.png", error, &nearly_spent), nullptr);
  EXPECT_EQ(error, "the image is 4x4 pixels, more than is left of the 268435456 pixels umbra decodes of one model's maps in all");
  TextureBudget enough;
  ASSERT_TRUE(enough.take(kMostModelTexturePixels - 16));
  error.clear();
  EXPECT_NE(decode_texture(png, "small.png", error, &enough), nullptr) << error;
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
  const PolygonSoup obj = read_polygon_soup(write("t.obj", kTriangleWithUvs), ReadOptions::skip());
  EXPECT_TRUE(obj.warnings.empty()) << obj.warnings[0].message;
  EXPECT_FALSE(obj.materials[0].texture);
  EXPECT_TRUE(obj.corner_uvs.empty());
  const PolygonSoup gltf = read_polygon_soup("/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", ReadOptions::skip());
  EXPECT_FALSE(gltf.materials[0].texture);
  EXPECT_TRUE(gltf.corner_uvs.empty());
}

TEST_F(TextureMapReading, AVtPastTheLastIsSaidAndTakesZero) {
  write_png_map("red blue.png");
  write("m.mtl", "newmtl painted\nmap_Kd red blue.png\n");
  const PolygonSoup soup = read_polygon_soup(write("t.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nusemtl painted\nf 1/1 2/9 3\n"));
  ASSERT_EQ(soup.warnings.size(), 1u);
  EXPECT_EQ(soup.warnings[0].message, "1 face corners name texture coordinates past the file's last (vt 9 of 1, the first): they take (0, 0)");
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

// KHR_texture_transform, on the extension's own sample model: each quad's
// corners take their TEXCOORD_0 through translation * rotation * scale, the
// turn u' = c u + s v, v' = -s u + c v (which puts the sample's arrows on
// its green markers). The untransformed marker quads share the quads'
// TEXCOORD_0 (accessor "UV0") corner by corner, so they give the input.
TEST(TextureMapsInGltf, KhrTextureTransformMapsEachCornersCoordinates) {
  const std::string path = "/usr/share/assimp/models/glTF2/textureTransform/TextureTransformTest.gltf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const PolygonSoup soup = read_polygon_soup(path);
  EXPECT_TRUE(soup.warnings.empty()) << soup.warnings[0].message;
  ASSERT_EQ(soup.corner_uvs.size(), soup.corners.size());
  // The first quad's six corners in each material, by name.
  const auto corners_of = [&](const std::string& name) {
    std::vector<glm::vec2> uvs;
    for (size_t p = 0; p < soup.polygon_count() && uvs.size() < 6; ++p)
      if (soup.materials[size_t(soup.polygon_material(p))].name == name)
        for (uint32_t c = soup.polygon_starts[p]; c < soup.polygon_starts[p + 1]; ++c) uvs.push_back(soup.corner_uvs[c]);
    return uvs;
  };
  const std::vector<glm::vec2> marker = corners_of("Correct"), offset_u = corners_of("Offset U"), offset_v = corners_of("Offset V"),
                               offset_uv = corners_of("Offset UV"), rotation = corners_of("Rotation"), scale = corners_of("Scale"),
                               all = corners_of("All");
  ASSERT_EQ(marker.size(), 6u);
  const auto expect_near = [](glm::vec2 got, glm::vec2 want) {
    EXPECT_NEAR(got.x, want.x, 1e-6);
    EXPECT_NEAR(got.y, want.y, 1e-6);
  };
  for (size_t k = 0; k < 6; ++k) {
    SCOPED_TRACE(k);
    // The offsets (0.5, 0), (0, 0.5), (0.5, 0.5) of the same UV1.
    expect_near(offset_uv[k] - offset_u[k], {0.0f, 0.5f});
    expect_near(offset_v[k] - offset_u[k], {-0.5f, 0.5f});
    const glm::vec2 uv = marker[k];
    const auto turned = [](glm::vec2 q, double r) {
      return glm::vec2(float(std::cos(r) * q.x + std::sin(r) * q.y), float(-std::sin(r) * q.x + std::cos(r) * q.y));
    };
    expect_near(rotation[k], turned(uv, 0.39269908169872414));
    expect_near(scale[k], 1.5f * uv);
    expect_near(all[k], turned(1.5f * uv, 0.3) + glm::vec2(-0.2f, -0.1f));
  }
}

TEST_F(TextureMapReading, AGltfWhoseImageIsMissingStillLoadsAndSaysSo) {
  const std::string box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/";
  for (const char* file : {"BoxTextured.gltf", "BoxTextured0.bin"})
    std::filesystem::copy_file(box + file, folder_ / file);  // not CesiumLogoFlat.png
  const PolygonSoup soup = read_polygon_soup((folder_ / "BoxTextured.gltf").string());
  ASSERT_EQ(soup.warnings.size(), 1u);
  EXPECT_EQ(soup.warnings[0].message,
            "material \"Texture\"'s base colour texture (CesiumLogoFlat.png) does not exist: its faces take the base colour");
  EXPECT_FALSE(soup.materials[0].texture);
  EXPECT_TRUE(soup.corner_uvs.empty());
  EXPECT_EQ(soup.polygon_count(), 12u);
}


// The safety of reading maps that a downloaded model names: only regular
// files (a FIFO would never answer, /dev/zero never end), only inside the
// folder the user named (else any image the user can read could be put into
// the picture), each file decoded once, and no image decoded past the budget.
class UntrustedMaps : public TextureMapReading {
 protected:
  // An OBJ triangle whose one material's map_Kd is `map`; its one warning, or "".
  std::string obj_map_warning(const std::string& map, const ReadOptions& maps = {}) const {
    write("m.mtl", "newmtl painted\nKd 0.5 0.5 0.5\nmap_Kd " + map + "\n");
    const PolygonSoup soup = read_polygon_soup(write("t.obj", kTriangleWithUvs), maps);
    EXPECT_LE(soup.warnings.size(), 1u);
    return soup.warnings.empty() ? "" : soup.warnings[0].message;
  }
  std::string refused(const std::string& map, const std::string& why) const {
    return "material \"painted\"'s texture map \"" + map + "\": " + why + ": its faces take the material's Kd colour";
  }
  // A PNG's signature and header chunk alone, claiming `width` x `height`
  // grey pixels: what stb_image reads before it decodes anything.
  static std::string png_header(uint32_t width, uint32_t height) {
    const auto be = [](std::string& out, uint32_t v) {
      for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xff);
    };
    std::string chunk = "IHDR";
    be(chunk, width), be(chunk, height);
    chunk += std::string("\x08\x00\x00\x00\x00", 5);  // 8-bit grey, deflate, no interlace
    std::string out = "\x89PNG\r\n\x1a\n";
    be(out, 13);
    out += chunk;
    be(out, test::crc32(chunk));
    return out;
  }
};

TEST_F(UntrustedMaps, AFifoOrADeviceIsNoMapAndNothingWaits) {
  const std::string fifo = (folder_ / "fifo.png").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(obj_map_warning("fifo.png"), refused(fifo, "is not a regular file (a FIFO), which umbra does not read as an image"));
  ReadOptions anywhere;
  anywhere.anywhere = true;
  EXPECT_EQ(obj_map_warning("/dev/zero", anywhere),
            refused("/dev/zero", "is not a regular file (a character device), which umbra does not read as an image"));
}

TEST_F(UntrustedMaps, AMapOutsideTheNamedFolderIsRefusedUnlessAnyPathIsAllowed) {
  std::filesystem::create_directories(folder_ / "pack" / "models");
  std::filesystem::create_directories(folder_ / "pack" / "textures");
  write_png_map("pack/textures/wood.png");
  write_png_map("secret.png");
  write_png_map("other secret.png");
  write("pack/models/m.mtl", "newmtl painted\nmap_Kd ../textures/wood.png\nnewmtl leak\nmap_Kd ../../secret.png\n"
                             "newmtl absolute\nmap_Kd " + (folder_ / "other secret.png").string() + "\n");
  const std::string obj = write("pack/models/t.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl painted\nf 1/1 2/1 3/1\n");
  const std::string pack = canonical(folder_ / "pack").string();
  const std::string outside = "lies outside " + pack + ", the folder umbra reads this model's files from (--any-texture-path reads it)";
  // The folder the user named: the pack. A sibling folder in it is read;
  // what climbs out of it, by ../ or by an absolute path, is not.
  ReadOptions maps;
  maps.root = (folder_ / "pack").string();
  const PolygonSoup soup = read_polygon_soup(obj, maps);
  ASSERT_EQ(soup.warnings.size(), 2u);
  EXPECT_TRUE(soup.materials[0].texture);
  EXPECT_EQ(soup.warnings[0].message, "material \"leak\"'s texture map \"" + (folder_ / "secret.png").string() + "\": " + outside +
                                          ": its faces take the material's Kd colour");
  EXPECT_EQ(soup.warnings[1].message, "material \"absolute\"'s texture map \"" + (folder_ / "other secret.png").string() + "\": " +
                                          outside + ": its faces take the material's Kd colour");
  // The mesh named on its own: its own folder.
  EXPECT_FALSE(read_polygon_soup(obj).materials[0].texture);
  maps.anywhere = true;
  const PolygonSoup anywhere = read_polygon_soup(obj, maps);
  EXPECT_TRUE(anywhere.warnings.empty());
  EXPECT_TRUE(anywhere.materials[1].texture && anywhere.materials[2].texture);
  // A link in the folder to a file outside it reads the file outside.
  std::filesystem::create_symlink(folder_ / "secret.png", folder_ / "pack" / "models" / "link.png");
  maps.anywhere = false;
  write("pack/models/m.mtl", "newmtl painted\nmap_Kd link.png\n");
  EXPECT_FALSE(read_polygon_soup(obj, maps).materials[0].texture);
}

TEST_F(UntrustedMaps, OneFileNamedByManyMaterialsIsDecodedOnceAndSaidOnce) {
  write_png_map("shared.png");
  std::string library, faces = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
  for (int m = 0; m < 200; ++m)
    library += "newmtl m" + std::to_string(m) + "\nmap_Kd shared.png\n", faces += "usemtl m" + std::to_string(m) + "\nf 1/1 2/1 3/1\n";
  write("m.mtl", library);
  const PolygonSoup soup = read_polygon_soup(write("t.obj", faces));
  ASSERT_EQ(soup.materials.size(), 200u);
  for (const SoupMaterial& m : soup.materials) EXPECT_EQ(m.texture.get(), soup.materials[0].texture.get());
  ASSERT_TRUE(soup.materials[0].texture);
  // A map that cannot be read, named by every material: said once.
  std::string zero_library;
  for (int m = 0; m < 200; ++m) zero_library += "newmtl m" + std::to_string(m) + "\nmap_Kd fifo.png\n";
  write("m.mtl", zero_library);
  ASSERT_EQ(::mkfifo((folder_ / "fifo.png").c_str(), 0600), 0);
  const PolygonSoup fifo = read_polygon_soup(write("t.obj", faces));
  ASSERT_EQ(fifo.warnings.size(), 1u);
  EXPECT_EQ(fifo.warnings[0].message.find("material \"m0\"'s texture map"), 0u) << fifo.warnings[0].message;
}

TEST_F(UntrustedMaps, AnImageLargerThanTheBudgetIsRefusedFromItsHeader) {
  write("wide.png", png_header(16385, 1));
  EXPECT_EQ(obj_map_warning("wide.png"), refused((folder_ / "wide.png").string(),
                                                 "the image is 16385x1 pixels, more than umbra decodes (16384 along a side, "
                                                 "67108864 pixels in all)"));
  write("huge.png", png_header(16384, 16384));  // 300 KB as a real PNG: 1 GiB decoded
  EXPECT_EQ(obj_map_warning("huge.png"), refused((folder_ / "huge.png").string(),
                                                 "the image is 16384x16384 pixels, more than umbra decodes (16384 along a side, "
                                                 "67108864 pixels in all)"));
}

TEST_F(UntrustedMaps, ATruncatedImageSaysSo) {
  const std::string whole = write_png_map("whole.png");
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  write("cut.png", bytes.substr(0, bytes.size() - 20));
  const std::string warning = obj_map_warning("cut.png");
  EXPECT_EQ(warning.find("material \"painted\"'s texture map \"" + (folder_ / "cut.png").string() +
                         "\": cannot decode the image: a PNG cut short or corrupt (stb_image: "),
            0u)
      << warning;
}

// glTF: the same rules for a uri, images decoded only when a material uses
// them, and once for every texture that names one image.
TEST_F(UntrustedMaps, GltfImagesFollowTheSameRules) {
  const PolygonSoup cube = test::unit_cube();
  const auto gltf_warnings = [&](const std::string& images, const std::string& textures, int materials) {
    test::GltfOptions o;
    o.material.clear();
    for (int m = 0; m < materials; ++m)
      o.material += std::string(m ? ", " : "") + R"({"name": "m)" + std::to_string(m) + R"(", "pbrMetallicRoughness": {"baseColorTexture": {"index": )" +
                    std::to_string(m) + "}}}";
    o.more = R"(, "images": [)" + images + R"(], "textures": [)" + textures + "]";
    const PolygonSoup soup = read_polygon_soup(write("m.gltf", test::gltf_json(cube, test::gltf_buffer(cube), o)));
    std::vector<std::string> said;
    for (const ReadWarning& w : soup.warnings) said.push_back(w.message);
    return std::make_pair(soup, said);
  };
  write_png_map("wood.png");
  const std::string fifo = (folder_ / "fifo.png").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  write("huge.png", png_header(16384, 16384));
  // Image 0 is used by all three textures; image 1, the huge one, by none;
  // 2 is a FIFO, 3 absolute, 4 a file: URI, 5 Windows' separators.
  std::filesystem::create_directories(folder_ / "sub");
  write_png_map("sub/a.png");
  const auto [soup, said] = gltf_warnings(
      R"({"uri": "wood.png"}, {"uri": "huge.png"}, {"uri": "fifo.png"}, {"uri": "/etc/hostname"}, {"uri": "file:///etc/x.png"}, {"uri": "sub\\a.png"})",
      R"({"source": 0}, {"source": 0}, {"source": 0}, {"source": 2}, {"source": 3}, {"source": 4}, {"source": 5})", 7);
  const std::string root = canonical(folder_).string();
  EXPECT_EQ(said, (std::vector<std::string>{
                      "material \"m3\"'s base colour texture (fifo.png) is not a regular file (a FIFO), which umbra does not read as "
                      "an image: its faces take the base colour",
                      "material \"m4\"'s base colour texture (/etc/hostname) lies outside " + root +
                          ", the folder umbra reads this model's files from (--any-texture-path reads it): its faces take the base colour",
                      "material \"m5\"'s base colour texture (file:///etc/x.png) is a file: URI, which umbra does not follow: name the "
                      "image by a path relative to the model: its faces take the base colour"}));
  ASSERT_TRUE(soup.materials[0].texture);
  EXPECT_EQ(soup.materials[1].texture.get(), soup.materials[0].texture.get());
  EXPECT_EQ(soup.materials[2].texture.get(), soup.materials[0].texture.get());
  EXPECT_TRUE(soup.materials[6].texture);  // sub\a.png
}

}  // namespace
}  // namespace umbra
