// Real files in the formats umbra reads through Assimp, from Debian's
// assimp-testmodels: each is read by the importer its name says, staged,
// and drawn with shadows that match exact shadow rays; textured ones draw
// their maps as the ray-cast reference does; a Draco-compressed glTF draws
// as its uncompressed twin.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mesh/io/mesh_file.hpp"
#include "scene/staged_scene.hpp"
#include "tests/render/image_agreement.hpp"
#include "tests/render/mask_comparison.hpp"

namespace umbra {
namespace {

const std::string kModels = "/usr/share/assimp/models/";

struct AssimpFile {
  const char* file;
  const char* importer;  // as umbra check's format says it
};

void PrintTo(const AssimpFile& f, std::ostream* out) { *out << f.file; }

class AssimpFormats : public ::testing::TestWithParam<AssimpFile> {};

TEST_P(AssimpFormats, ReadByItsImporterAndShadowedAsExactRaysShadowIt) {
  const std::string path = kModels + GetParam().file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing (build.sh installs assimp-testmodels)";
  EXPECT_EQ(read_polygon_soup(path, ReadOptions::skip()).format, std::string("read through Assimp's ") + GetParam().importer);
  const Scene scene = parse_scene_or_mesh_file(path);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_GT(scene.meshes[0].triangles.size(), 0u);
  test::expect_masks_match_reference(scene, 48, 48, 64);
}

INSTANTIATE_TEST_SUITE_P(
    RealFiles, AssimpFormats,
    ::testing::Values(AssimpFile{"3DS/fels.3ds", "Discreet 3DS Importer"}, AssimpFile{"Collada/duck.dae", "Collada Importer"},
                      AssimpFile{"FBX/spider.fbx", "Autodesk FBX Importer"}, AssimpFile{"BLEND/HUMAN.blend", "Blender 3D Importer"},
                      AssimpFile{"X/test.x", "Direct3D XFile Importer"}, AssimpFile{"AC/Wuson.ac", "AC3D Importer"},
                      AssimpFile{"MS3D/jeep1.ms3d", "Milkshape 3D Importer"},
                      AssimpFile{"LWO/LWO2/concave_polygon.lwo", "LightWave/Modo Object Importer"},
                      AssimpFile{"glTF/TwoBoxes/TwoBoxes.gltf", "glTF Importer"},
                      AssimpFile{"AMF/test1.amf", "Additive manufacturing file format(AMF) Importer"}),
    [](const ::testing::TestParamInfo<AssimpFile>& info) {
      std::string name = std::filesystem::path(info.param.file).stem().string();
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

// Maps beside the file: Collada's duck, a DirectX cube, and a 3DS cube
// whose map's name is in capitals (TEST.PNG for test.png). Each draws its
// map as the reference does, and the map's colours show: the stage's grey
// model and floor have none.
TEST(AssimpMaps, EachTexturedFileDrawsItsMapAsTheReferenceDoes) {
  for (const char* file : {"Collada/duck.dae", "X/test.x", "3DS/cube_with_diffuse_texture.3DS"}) {
    SCOPED_TRACE(file);
    const std::string path = kModels + file;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing";
    const Scene scene = parse_scene_or_mesh_file(path);
    ASSERT_FALSE(scene.meshes[0].triangle_uvs.empty());
    const test::RenderedImages r = test::render_gl_and_ray_cast(scene, 96);
    test::expect_images_agree(scene, r);
    int coloured = 0;
    for (int y = 0; y < 96; ++y)
      for (int x = 0; x < 96; ++x) {
        const int a = r.gl.at(x, y, 0), b = r.gl.at(x, y, 1), c = r.gl.at(x, y, 2);
        coloured += std::max({a, b, c}) - std::min({a, b, c}) > 80;
      }
    EXPECT_GT(coloured, 300);
  }
}

// Khronos's engine, Draco-compressed (KHR_draco_mesh_compression, through
// Assimp's glTF importer) and not: the same model, to the compression's
// quantisation, staged the same.
TEST(AssimpMaps, ADracoGltfDrawsAsItsUncompressedTwin) {
  const std::string draco = kModels + "glTF2/draco/2CylinderEngine.gltf";
  const std::string plain = kModels + "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  if (!std::filesystem::exists(draco) || !std::filesystem::exists(plain)) GTEST_SKIP() << "assimp-testmodels is missing";
  const Scene a = parse_scene_or_mesh_file(draco), b = parse_scene_or_mesh_file(plain);
  // Quantisation collapses a few sliver triangles (10 of 110,336) to lines.
  EXPECT_NEAR(double(a.meshes[0].triangles.size()), double(b.meshes[0].triangles.size()), 20.0);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(a.meshes[0].file_bounds_min[axis], b.meshes[0].file_bounds_min[axis], 1e-3 * 740);
    EXPECT_NEAR(a.meshes[0].file_bounds_max[axis], b.meshes[0].file_bounds_max[axis], 1e-3 * 740);
  }
  test::expect_masks_match_reference(a, 48, 48, 64);
}

}  // namespace
}  // namespace umbra
