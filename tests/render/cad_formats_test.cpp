// CAD exchange files from Debian's occt-misc, through Open CASCADE: each
// tessellated, staged and drawn with shadows that match exact shadow rays;
// a solid is a closed mesh, every component casting from its silhouette.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mesh/io/mesh_file.hpp"
#include "scene/staged_scene.hpp"
#include "tests/render/mask_comparison.hpp"

namespace umbra {
namespace {

struct CadFile {
  const char* file;
  const char* format;
  bool solid;  // a solid, tessellated closed
};

void PrintTo(const CadFile& f, std::ostream* out) { *out << f.file; }

class CadFormats : public ::testing::TestWithParam<CadFile> {};

TEST_P(CadFormats, TessellatedAndShadowedAsExactRaysShadowIt) {
  const std::string path = std::string("/usr/share/opencascade/data/") + GetParam().file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing (build.sh installs occt-misc)";
  EXPECT_EQ(read_polygon_soup(path, ReadOptions::skip()).format, std::string(GetParam().format) + ", tessellated by Open CASCADE");
  const Scene scene = parse_scene_or_mesh_file(path);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const SilhouetteComponents& c = scene.meshes[0].components;
  if (GetParam().solid) {
    EXPECT_EQ(c.silhouette_components, c.components);
  }
  test::expect_masks_match_reference(scene, 48, 48, 64);
}

INSTANTIATE_TEST_SUITE_P(OcctMisc, CadFormats,
                         ::testing::Values(CadFile{"step/screw.step", "STEP", true}, CadFile{"step/linkrods.step", "STEP", true},
                                           CadFile{"iges/hammer.iges", "IGES", false}, CadFile{"occ/bottle.brep", "BREP", true}),
                         [](const ::testing::TestParamInfo<CadFile>& info) {
                           std::string name = std::filesystem::path(info.param.file).filename().string();
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace umbra
