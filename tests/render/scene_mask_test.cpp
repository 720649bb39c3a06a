// End to end through OSMesa: every bundled scene's shadow mask, for every
// light, against exact shadow rays on the CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "mask_comparison.hpp"
#include "mesh/scene_checks.hpp"
#include "mesh/scene_parser.hpp"
#include "render/headless_context.hpp"
#include "render/shadow_renderer.hpp"

namespace umbra {
namespace {

std::string scene_path(const std::string& name) { return std::string(UMBRA_SOURCE_DIR) + "/scenes/" + name; }

class BundledScene : public testing::TestWithParam<std::string> {};

TEST_P(BundledScene, MaskMatchesExactShadowRays) {
  test::expect_masks_match_reference(parse_scene_file(scene_path(GetParam())), 240, 180, 64);
}

TEST_P(BundledScene, MaskMatchesExactShadowRaysWithTheLightRotated) {
  test::expect_masks_match_reference(parse_scene_file(scene_path(GetParam())), 160, 160, 32, 137.0);
}

std::vector<std::string> bundled_scenes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(UMBRA_SOURCE_DIR) + "/scenes"))
    if (entry.path().extension() == ".scene") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledScene, testing::ValuesIn(bundled_scenes()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(ZFail, EyeInsideAShadowVolumeStillGetsCorrectShadows) {
  const Scene scene = parse_scene_file(scene_path("camera_in_shadow.scene"));
  // The premise: the eye is in the shadow of light 1 (z-pass would miscount).
  ASSERT_TRUE(shadow_ray_blocked(scene, scene.camera.eye, -1, scene.lights[0].position));
  test::expect_masks_match_reference(scene, 200, 200, 64);
}

TEST(ZFail, SphereShadowErrorIsConfinedToTheNgonBand) {
  // With a coarse hexagon (spec figure 7) the band is wide; every difference
  // must still be explained by it or by a pixel edge.
  test::expect_masks_match_reference(parse_scene_file(scene_path("two_spheres.scene")), 200, 200, 6);
}

TEST(Shading, LitAndShadowedFloorPixelsHaveThePhongValues) {
  // Floor (diffuse 0.8, ambient 1) lit from straight above; a triangle shades part of it.
  const Scene scene = parse_scene_text(
      "light 0 0 2\n"
      "triangle -1 -1 -1  1 -1 -1  1 1 -1\n"
      "triangle 0.2 0.2 0  0.6 0.2 0  0.2 0.6 0\n",
      "floor.scene");
  RenderSettings settings;
  settings.width = settings.height = 101;  // pixel (50, 50) looks straight down the axis
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(settings.width, settings.height);
  ShadowRenderer renderer(scene, plan);
  const Image image = renderer.render_image(false);
  // Centre: floor point (0, 0, -1), n = l = +z: 0.15 ambient + 0.8 diffuse = 0.95.
  EXPECT_NEAR(image.at(50, 50, 0), 0.95 * 255, 1.0);
  // A floor point in the triangle's shadow gets the ambient term alone.
  int shadowed = 0;
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      const auto hit = nearest_hit(scene, scene.camera.eye, pixel_ray_direction(scene.camera, 101, 101, x, y));
      if (!hit || hit->object != 0 || reference_mask_value(scene, 101, 101, x, y, 0) != kMaskUnlit) continue;
      if (reference_mask_value(scene, 101, 101, x - 0.5, y - 0.5, 0) != kMaskUnlit ||
          reference_mask_value(scene, 101, 101, x + 0.5, y + 0.5, 0) != kMaskUnlit)
        continue;  // skip the shadow's edge pixels
      EXPECT_NEAR(image.at(x, y, 0), 0.15 * 255, 1.0) << x << ", " << y;
      ++shadowed;
    }
  EXPECT_GT(shadowed, 20);
}

TEST(ShowVolumes, DrawsTheVolumesOverTheImage) {
  const Scene scene = parse_scene_file(scene_path("demo.scene"));
  RenderSettings settings;
  settings.width = settings.height = 120;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(settings.width, settings.height);
  ShadowRenderer renderer(scene, plan);
  const Image plain = renderer.render_image(false);
  const Image shown = renderer.render_image(true);
  int changed = 0;
  for (size_t i = 0; i < plain.pixels.size(); ++i) changed += plain.pixels[i] != shown.pixels[i];
  EXPECT_GT(changed, int(plain.pixels.size() / 20));
  EXPECT_EQ(renderer.render_image(false).pixels, plain.pixels);  // the overlay leaves no state behind
}

}  // namespace
}  // namespace umbra
