// A mesh file rendered on its own: the scene umbra stages for it (fitted into
// the cube over a floor, one light), its text saved and read back as the same
// scene, and its shadow masks against exact shadow rays, for a mesh the tests
// write and for a real exported model.
#include <filesystem>

#include <gtest/gtest.h>

#include "hard_case_scenes.hpp"
#include "mask_comparison.hpp"
#include "scene/staged_scene.hpp"
#include "tests/mesh/interchange_writers.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

// A torus at its native size, far from the origin, as glTF binary.
std::string write_torus_glb() {
  PolygonSoup torus = test::triangulated(test::quad_torus(24, 12, 40.0, 10.0));
  for (glm::dvec3& p : torus.points) p += glm::dvec3(300, -200, 50);
  const std::string buffer = test::gltf_buffer(torus);
  test::GltfOptions tilted;
  tilted.node = R"("mesh": 0, "rotation": [0.3826834, 0, 0, 0.9238795])";  // 45 degrees about x
  return test::write_mesh("torus.glb", test::glb(test::gltf_json(torus, buffer, tilted, true), buffer));
}

TEST(StagedMesh, AMeshFileIsToldFromASceneByItsContent) {
  EXPECT_TRUE(is_mesh_file(write_torus_glb()));
  EXPECT_TRUE(is_mesh_file(test::write_mesh("cube-no-extension", test::obj_text(test::unit_cube()))));
  EXPECT_FALSE(is_mesh_file(test::write_mesh("s.scene", "light 0 0 2\n")));
  EXPECT_FALSE(is_mesh_file(test::write_mesh("scene-no-extension", "light 0 0 2\nsphere 0 0 0 0.5\n")));
  EXPECT_FALSE(is_mesh_file("/nonexistent/mesh.obj"));
  const std::string quoted = test::write_mesh("say \"cheese\".obj", test::obj_text(test::unit_cube()));
  try {
    parse_scene_or_mesh_file(quoted);
    ADD_FAILURE() << "a file name with a double quote was staged";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), quoted + ": a scene cannot name a file whose name holds a double quote: rename it to stage it");
  }
}

TEST(StagedMesh, WarningsAndErrorsNameTheMeshFileNotTheStagedScene) {
  // An open box: its warning belongs to the file, not to line 7 of a scene
  // the user never wrote.
  const std::string open = test::write_mesh("open-box.obj", test::obj_text(test::without_faces(test::unit_cube(), {0, 1})));
  const Scene scene = parse_scene_or_mesh_file(open);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0].where.str(), open);
  EXPECT_EQ(scene.warnings[0].message, "mesh \"open-box.obj\" is open, 1 hole: edge-multiplicity volume");
  // A file-level error: said of the file, once.
  const std::string point = test::write_mesh("point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
  try {
    parse_scene_or_mesh_file(point);
    ADD_FAILURE() << "a mesh without area was staged";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), point + ": has no faces with area to fit");
  }
}

TEST(StagedMesh, FitsTheMeshIntoTheCubeOverTheFloorUnderOneLight) {
  const std::string path = write_torus_glb();
  std::string text;
  const Scene scene = parse_scene_or_mesh_file(path, {}, &text);
  EXPECT_EQ(text, staged_scene_text(path));
  EXPECT_EQ(scene.path, path + " (staged)");
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_GT(scene.lights[0].position.z, 1.0);
  ASSERT_EQ(scene.triangles.size(), 2u);  // the floor: the cube's back face
  for (const Triangle& t : scene.triangles) EXPECT_EQ(std::max({t.a.z, t.b.z, t.c.z}), -1.0);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& m = scene.meshes[0];
  // Centred, its longest side 0.8 of the cube's.
  const glm::dvec3 size = m.bounds_max - m.bounds_min;
  EXPECT_NEAR(std::max({size.x, size.y, size.z}), 1.6, 1e-12);
  EXPECT_NEAR(glm::length(m.bounds_min + m.bounds_max), 0.0, 1e-12);
  EXPECT_TRUE(m.components.all_closed());
  EXPECT_TRUE(scene.warnings.empty());
  EXPECT_FALSE(scene.camera_from.has_value());  // the default view

  // The text, saved beside the mesh, is the same scene.
  const std::string saved = (std::filesystem::path(path).parent_path() / "torus.scene").string();
  std::ofstream(saved) << text;
  const Scene again = parse_scene_file(saved);
  EXPECT_EQ(again.meshes[0].positions.points(), m.positions.points());
}

TEST(StagedMesh, MaskMatchesExactShadowRays) {
  test::expect_masks_match_reference(parse_scene_or_mesh_file(write_torus_glb()), 160, 160, 64);
}

// A real exported model: the two-cylinder engine of Khronos's glTF sample
// models, as Debian's assimp-testmodels ships it (121,496 faces, of which
// 11,160 repeat a vertex once equal points merge, so 110,336 triangles; 96
// components, 67 of them open; at its native size of about +-370), as
// umbra check reports it.
TEST(StagedMesh, RealEngineModelMaskMatchesExactShadowRays) {
  const std::string engine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  if (!std::filesystem::exists(engine)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const Scene scene = parse_scene_or_mesh_file(engine);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].triangles.size(), 110336u);
  EXPECT_EQ(scene.meshes[0].components.components, 96u);
  EXPECT_EQ(scene.meshes[0].components.closed_components, 29u);
  // Small: the reference casts every pixel's rays against every triangle.
  test::expect_masks_match_reference(scene, 64, 64, 64);
}

}  // namespace
}  // namespace umbra
