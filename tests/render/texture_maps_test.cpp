// Texture maps drawn: the GL samples them as the ray-cast reference does
// (bilinear, no mipmaps, the map's wrap modes), so the two images agree
// away from the edges of objects, on a map of our own and on Khronos's
// textured box.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>

#include "image/image.hpp"
#include "scene/scene_parser.hpp"
#include "scene/staged_scene.hpp"
#include "tests/render/image_agreement.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

class TextureMapsDrawn : public test::ScratchFolder {};

// A floor twice tiled with a 4 x 4 map of ramps (and at the wrap, steps), a
// sphere's shadow across it.
TEST_F(TextureMapsDrawn, AnObjFloorsMapMatchesTheReference) {
  Image map(4, 4, 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      map.at(x, y, 0) = uint8_t(100 + 25 * x);
      map.at(x, y, 1) = uint8_t(100 + 25 * y);
      map.at(x, y, 2) = uint8_t(120 + 15 * (x + y));
    }
  write_png(map, (folder_ / "tiles.png").string());
  write("floor.mtl", "newmtl tiled\nKd 1 1 1\nmap_Kd tiles.png\n");
  write("floor.obj", "mtllib floor.mtl\nv -1 -1 -0.5\nv 1 -1 -0.5\nv 1 1 -0.5\nv -1 1 -0.5\n"
                     "vt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\nusemtl tiled\nf 1/1 2/2 3/3 4/4\n");
  const Scene scene = parse_scene_text("light 0.3 0.2 3\nmesh floor.obj\nsphere 0 0 0 0.25\n", (folder_ / "t.scene").string());
  ASSERT_TRUE(scene.materials.back().texture);
  for (const RenderMethod method : {RenderMethod::kAuto, RenderMethod::kShadowMap}) {
    SCOPED_TRACE(method_name(method));
    const test::RenderedImages r = test::render_gl_and_ray_cast(scene, 96, method);
    if (method == RenderMethod::kAuto) test::expect_images_agree(scene, r);
    // The map shows: the floor's lit pixels are far from one colour.
    int lowest = 255, highest = 0;
    for (int x = 20; x < 76; ++x) lowest = std::min<int>(lowest, r.gl.at(x, 30, 0)), highest = std::max<int>(highest, r.gl.at(x, 30, 0));
    EXPECT_GT(highest - lowest, 30);
  }
}

// A glTF floor whose texture coordinates run from -1.25 to 2.25, so that
// each of its sampler's wrap modes shows, under a 4 x 4 map whose red
// alternates between 0 and 255: filtered with a few bits of sub-texel
// precision, as GL_LINEAR may be (llvmpipe's is), such a map puts pixels two
// levels from the reference.
TEST_F(TextureMapsDrawn, EachWrapModeOfAnExtremeMapMatchesTheReference) {
  Image map(4, 4, 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      map.at(x, y, 0) = uint8_t((x + y) % 2 ? 255 : 0);
      map.at(x, y, 1) = uint8_t(85 * x);
      map.at(x, y, 2) = uint8_t(85 * y);
    }
  write_png(map, (folder_ / "checker.png").string());
  const float positions[] = {-1, -1, -0.5f, 1, -1, -0.5f, 1, 1, -0.5f, -1, 1, -0.5f};
  const float uvs[] = {-1.25f, 2.25f, 2.25f, 2.25f, 2.25f, -1.25f, -1.25f, -1.25f};
  const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
  std::string bytes(reinterpret_cast<const char*>(positions), sizeof positions);
  bytes.append(reinterpret_cast<const char*>(uvs), sizeof uvs).append(reinterpret_cast<const char*>(indices), sizeof indices);
  write("floor.bin", bytes);
  const auto floor_gltf = [](int wrap_s, int wrap_t) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0, "sampler": 0}], "images": [{"uri": "checker.png"}],
  "samplers": [{"magFilter": 9729, "minFilter": 9729, "wrapS": )" +
           std::to_string(wrap_s) + R"(, "wrapT": )" + std::to_string(wrap_t) + R"(}],
  "buffers": [{"uri": "floor.bin", "byteLength": 92}],
  "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, -0.5], "max": [1, 1, -0.5]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
  };
  constexpr int kRepeat = 10497, kMirroredRepeat = 33648, kClampToEdge = 33071;
  for (const auto& [wrap_s, wrap_t] : {std::pair{kRepeat, kRepeat}, {kMirroredRepeat, kClampToEdge}, {kClampToEdge, kMirroredRepeat}}) {
    SCOPED_TRACE("wrapS " + std::to_string(wrap_s) + ", wrapT " + std::to_string(wrap_t));
    write("floor.gltf", floor_gltf(wrap_s, wrap_t));
    const Scene scene = parse_scene_text("light 0.3 0.2 3\nmesh floor.gltf\nsphere 0 0 0 0.25\n", (folder_ / "t.scene").string());
    ASSERT_TRUE(scene.materials.back().texture);
    const test::RenderedImages r = test::render_gl_and_ray_cast(scene, 96);
    test::expect_images_agree(scene, r);
  }
}

TEST_F(TextureMapsDrawn, KhronossTexturedBoxMatchesTheReference) {
  const Scene scene = parse_scene_or_mesh_file("/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].triangle_uvs.size(), 12u);
  const test::RenderedImages r = test::render_gl_and_ray_cast(scene, 160);
  test::expect_images_agree(scene, r);
  // The Cesium logo's blue and green show on the box.
  int blue = 0, green = 0;
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 160; ++x) {
      const int red = r.gl.at(x, y, 0), g = r.gl.at(x, y, 1), b = r.gl.at(x, y, 2);
      blue += b > red + 40 && b > g;
      green += g > red + 30 && g > b + 30;
    }
  EXPECT_GT(blue, 200);
  EXPECT_GT(green, 200);
}

}  // namespace
}  // namespace umbra
