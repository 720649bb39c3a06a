// An orthographic camera: parallel rays from its eye's plane. Its shadow
// volumes cannot reach infinity (no orthographic picture holds it), so they
// stop at a finite reach, and are drawn with depth clamping; its masks must
// match exact shadow rays as a perspective's do, and its pictures the
// ray-cast reference's.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "image_agreement.hpp"
#include "mask_comparison.hpp"
#include "render/render_plan.hpp"
#include "scene/scene_parser.hpp"
#include "scene/staged_scene.hpp"

namespace umbra {
namespace {

std::string scene_path(const std::string& name) { return std::string(UMBRA_SOURCE_DIR) + "/scenes/" + name; }

// The bundled scene, seen orthographically along its own camera's axis, as
// high as its perspective saw at the target.
Scene orthographic(Scene scene) {
  const double distance = glm::length(scene.camera.target - scene.camera.eye);
  scene.camera.ortho_height = 2.0 * distance * scene.camera.half_height_at_unit_depth();
  return scene;
}

class OrthographicScene : public testing::TestWithParam<const char*> {};

TEST_P(OrthographicScene, MaskMatchesExactShadowRays) {
  const Scene scene = orthographic(parse_scene_file(scene_path(GetParam())));
  test::expect_masks_match_reference(scene, 200, 150, 64);
  test::expect_masks_match_reference(scene, 160, 160, 32, 137.0);
}

TEST_P(OrthographicScene, PictureMatchesTheRayCastReference) {
  const Scene scene = orthographic(parse_scene_file(scene_path(GetParam())));
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
}

INSTANTIATE_TEST_SUITE_P(Bundled, OrthographicScene,
                         testing::Values("two_spheres.scene", "demo.scene", "stacked.scene", "triangles.scene", "many_spheres.scene",
                                         "camera_in_shadow.scene", "colored_lights.scene", "mesh_torus.scene", "mesh_open_box.scene"));

// A light among its casters on every axis: no box face bounds the volumes,
// so the orthographic camera's reach comes from the light's distance to the
// nearest caster (finite_volume_reach), and the masks stay exact.
TEST(Orthographic, ALightAmongItsCastersHasAFiniteReachAndExactShadows) {
  const Scene scene = parse_scene_text(
      "light 0 0 0.2\n"
      "sphere 0.6 0 0.2 0.15\nsphere -0.6 0.1 0.2 0.15\nsphere 0 0.6 0.25 0.12\nsphere 0.1 -0.6 0.1 0.12\n"
      "sphere 0 0 0.75 0.1\n"
      "triangle -1 -1 -0.5  1 -1 -0.5  1 1 -0.5\ntriangle -1 -1 -0.5  1 1 -0.5  -1 1 -0.5\n"
      "camera eye 0.3 -2.5 2.5 target 0 0 0 up 0 0 1 orthographic 2.6\n",
      "among.scene");
  RenderSettings settings;
  settings.width = settings.height = 160;
  const RenderPlan plan = make_render_plan(scene, settings);
  ASSERT_TRUE(std::isfinite(plan.lights[0].volume_reach));
  EXPECT_GT(plan.lights[0].volume_reach, 1.0);
  test::expect_masks_match_reference(scene, 160, 160, 64);
}

// Staged meshes, --orthographic: the model and its shadow framed, shadows exact.
TEST(Orthographic, StagedMeshMasksMatchExactShadowRays) {
  StagingOptions staging;
  staging.view.orthographic = true;
  std::vector<std::string> meshes = {scene_path("meshes/torus.obj"), scene_path("meshes/open_box.obj")};
  const std::string engine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  if (std::filesystem::exists(engine)) meshes.push_back(engine);
  for (const std::string& mesh : meshes) {
    SCOPED_TRACE(mesh);
    const Scene scene = parse_scene_or_mesh_file(mesh, {}, nullptr, staging);
    ASSERT_TRUE(scene.camera.orthographic());
    const bool large = scene.meshes[0].triangles.size() > 10000;  // the reference's rays search it by brute force
    test::expect_masks_match_reference(scene, large ? 80 : 160, large ? 60 : 120, 64);
  }
}

}  // namespace
}  // namespace umbra
