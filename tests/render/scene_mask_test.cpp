// End to end through OSMesa: every bundled scene's shadow mask, for every
// light, against exact shadow rays on the CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "mask_comparison.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_parser.hpp"
#include "render/headless_context.hpp"
#include "image/mask_error.hpp"
#include "scene/camera.hpp"
#include "reference/ray_cast.hpp"
#include "reference/ray_cast_render.hpp"
#include "render/shadow_renderer.hpp"

namespace umbra {
namespace {

std::string scene_path(const std::string& name) { return std::string(UMBRA_SOURCE_DIR) + "/scenes/" + name; }

class BundledScene : public testing::TestWithParam<std::string> {};

TEST(MaskComparison, AMaskShiftedByOnePixelFailsWhereTheRightOnePasses) {
  const Scene scene = parse_scene_file(scene_path("demo.scene"));
  RenderSettings settings;
  settings.width = settings.height = 120;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(120, 120);
  ShadowRenderer renderer(scene, plan);
  const Image mask = renderer.render_mask(0);
  const test::MaskComparison right = test::compare_with_reference(scene, plan, mask, 0);
  EXPECT_EQ(right.unexplained, 0);
  EXPECT_TRUE(test::within_boundary_bound(right));
  for (const auto& [dx, dy] : {std::pair{1, 0}, {0, 1}, {-1, 0}, {0, -1}}) {
    Image shifted = mask;
    for (int y = 0; y < 120; ++y)
      for (int x = 0; x < 120; ++x) shifted.at(x, y) = mask.at(std::clamp(x - dx, 0, 119), std::clamp(y - dy, 0, 119));
    const test::MaskComparison wrong = test::compare_with_reference(scene, plan, shifted, 0);
    // The bound alone catches it (about a third of the boundary pixels are
    // excused), and so do the pixels a whole pixel from any edge.
    EXPECT_FALSE(test::within_boundary_bound(wrong))
        << dx << ", " << dy << ": " << wrong.excused_boundary << " excused of " << wrong.boundary_pixels;
    EXPECT_GT(wrong.unexplained, 0);
  }
}

TEST_P(BundledScene, MaskMatchesExactShadowRays) {
  test::expect_masks_match_reference(parse_scene_file(scene_path(GetParam())), 240, 180, 64);
}

TEST_P(BundledScene, MaskMatchesExactShadowRaysWithTheLightRotated) {
  test::expect_masks_match_reference(parse_scene_file(scene_path(GetParam())), 160, 160, 32, 137.0);
}

TEST_P(BundledScene, ZFailForEveryLightMatchesExactShadowRays) {
  test::expect_masks_match_reference(parse_scene_file(scene_path(GetParam())), 160, 120, 64, 0.0, RenderMethod::kZFail);
}

TEST_P(BundledScene, PerTriangleMeshVolumesMatchExactShadowRays) {
  test::expect_masks_match_reference(parse_scene_file(scene_path(GetParam())), 160, 120, 64, 0.0, RenderMethod::kTriangles);
}

// Where auto counts a light with z-pass (the near plane outside every
// volume), z-pass without caps and capped z-fail count the same closed
// surfaces, so their masks agree pixel for pixel.
TEST_P(BundledScene, ZPassAndZFailAgreeWhereverAutoChoosesZPass) {
  for (const double angle : {0.0, 137.0}) {
    Scene scene = parse_scene_file(scene_path(GetParam()));
    rotate_lights_about_z(scene, angle);
    RenderSettings settings;
    settings.width = settings.height = 160;
    const RenderPlan automatic = make_render_plan(scene, settings);
    settings.method = RenderMethod::kZPass;
    const RenderPlan zpass = make_render_plan(scene, settings);
    settings.method = RenderMethod::kZFail;
    const RenderPlan zfail = make_render_plan(scene, settings);
    HeadlessContext context(settings.width, settings.height);
    ShadowRenderer pass_renderer(scene, zpass), fail_renderer(scene, zfail);
    for (size_t light = 0; light < scene.lights.size(); ++light) {
      if (automatic.lights[light].count != DepthCount::kWhereDepthPasses) continue;
      const Image a = pass_renderer.render_mask(light), b = fail_renderer.render_mask(light);
      int differing = 0;
      for (size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
      EXPECT_EQ(differing, 0) << "light " << light + 1 << " at " << angle << " deg";
    }
  }
}

// umbra render --mask draws the image first; at one sample a pixel the mask
// of the light cast last is drawn over that image's depth and cast. For
// every GL method, every light (the last cast and the others) and both
// sample counts, that mask is the one a renderer draws from nothing.
TEST_P(BundledScene, MaskAfterTheImageIsTheMaskDrawnAlone) {
  const Scene scene = parse_scene_file(scene_path(GetParam()));
  for (const RenderMethod method : all_methods()) {
    if (method == RenderMethod::kRaycast) continue;
    for (const int samples : {1, 3}) {
      RenderSettings settings;
      settings.width = 96;
      settings.height = 72;
      settings.method = method;
      settings.antialias = samples;
      const RenderPlan plan = make_render_plan(scene, settings);
      HeadlessContext context(settings.width, settings.height);
      ShadowRenderer after_image(scene, plan), alone(scene, plan);
      for (size_t light = 0; light < scene.lights.size(); ++light) {
        const auto [image, mask] = after_image.render_image_and_mask(false, light);
        EXPECT_TRUE(image.pixels == after_image.render_image(false).pixels);
        EXPECT_TRUE(mask.pixels == alone.render_mask(light).pixels)
            << method_name(method) << ", " << samples << " x " << samples << " samples, light " << light + 1;
      }
    }
  }
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

TEST(ZFail, ErrorAgainstTheReferenceFallsAsNGrows) {
  const Scene scene = parse_scene_file(scene_path("two_spheres.scene"));
  const RayCastFrame reference = ray_cast_frame(scene, 200, 200);
  HeadlessContext context(200, 200);
  long previous = -1;
  for (const int n : {64, 32, 16, 8}) {  // coarser each time
    RenderSettings settings;
    settings.width = settings.height = 200;
    settings.sphere_segments = n;
    settings.method = RenderMethod::kZFail;
    const RenderPlan plan = make_render_plan(scene, settings);
    ShadowRenderer renderer(scene, plan);
    const MaskError e = mask_error(reference.masks[0], renderer.render_mask(0));
    EXPECT_GT(e.wrong_pixels, previous) << "N = " << n;
    previous = e.wrong_pixels;
  }
}

// Planar projection is exact where every shadow falls on a plane: these
// scenes' shadows all land on their triangles.
TEST(Planar, MatchesExactShadowRaysWhereEveryReceiverIsAPlane) {
  for (const char* name : {"triangles.scene", "two_spheres.scene", "camera_in_shadow.scene", "mesh_icosphere.scene"})
    test::expect_masks_match_reference(parse_scene_file(scene_path(name)), 160, 120, 64, 0.0, RenderMethod::kPlanar);
}

// ... and leaves spheres unshadowed: in stacked.scene spheres shadow spheres.
TEST(Planar, SpheresReceiveNoShadowAndThePlanSaysSo) {
  const Scene scene = parse_scene_file(scene_path("stacked.scene"));
  RenderSettings settings;
  settings.width = settings.height = 160;
  settings.method = RenderMethod::kPlanar;
  const RenderPlan plan = make_render_plan(scene, settings);
  EXPECT_NE(plan.lights[0].count_reason.find("spheres and meshes receive no shadow"), std::string::npos);
  HeadlessContext context(160, 160);
  ShadowRenderer renderer(scene, plan);
  const test::MaskComparison r = test::compare_with_reference(scene, plan, renderer.render_mask(0), 0);
  EXPECT_GT(r.unexplained, 100);
  // Every unexplained pixel is a sphere lit by planar and shadowed by the reference.
  const Image mask = renderer.render_mask(0);
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 160; ++x) {
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(160, 160, x, y));
      if (hit && hit->object >= int(scene.spheres.size())) continue;  // planes: the test above
      if (mask.at(x, y) != reference_mask_value(scene, 160, 160, x, y, 0)) {
        EXPECT_EQ(mask.at(x, y), kMaskLit);
      }
    }
}

// Shadow mapping's error is the map's texel: it shrinks as the map grows.
TEST(ShadowMap, ErrorAgainstTheReferenceFallsAsTheMapGrows) {
  const Scene scene = parse_scene_file(scene_path("demo.scene"));
  const RayCastFrame reference = ray_cast_frame(scene, 200, 200);
  HeadlessContext context(200, 200);
  long previous = -1;
  for (const int size : {2048, 256, 32}) {  // coarser each time
    RenderSettings settings;
    settings.width = settings.height = 200;
    settings.method = RenderMethod::kShadowMap;
    settings.shadow_map_size = size;
    const RenderPlan plan = make_render_plan(scene, settings);
    EXPECT_TRUE(plan.lights[0].casters.empty()) << "no volumes for a shadow map";
    ShadowRenderer renderer(scene, plan);
    const MaskError e = mask_error(reference.masks[0], renderer.render_mask(0));
    EXPECT_GT(e.wrong_pixels, previous) << "map " << size;
    previous = e.wrong_pixels;
  }
}

// Away from the shadow's edge a shadow map is right: the floor under a
// small triangle lit from the side, whose shadow (0.2, -0.3), (0.8, -0.3),
// (0.2, 0.3) the eye sees mostly beside the triangle.
TEST(ShadowMap, LitAndShadowedFloorAwayFromTheEdges) {
  const Scene scene = parse_scene_text(
      "light -1 0 2\n"
      "triangle -1 -1 -1  1 -1 -1  1 1 -1\n"
      "triangle -1 -1 -1  1 1 -1  -1 1 -1\n"
      "triangle -0.2 -0.2 0  0.2 -0.2 0  -0.2 0.2 0\n",
      "floor.scene");
  RenderSettings settings;
  settings.width = settings.height = 101;
  settings.method = RenderMethod::kShadowMap;
  settings.shadow_map_size = 512;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(101, 101);
  ShadowRenderer renderer(scene, plan);
  const Image mask = renderer.render_mask(0);
  int checked = 0, shadowed = 0;
  for (int y = 2; y < 99; ++y)
    for (int x = 2; x < 99; ++x) {
      const uint8_t ref = reference_mask_value(scene, 101, 101, x, y, 0);
      bool uniform = true;  // two pixels round it in every direction agree
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) uniform = uniform && reference_mask_value(scene, 101, 101, x + dx, y + dy, 0) == ref;
      if (!uniform) continue;
      EXPECT_EQ(mask.at(x, y), ref) << x << ", " << y;
      ++checked;
      shadowed += ref == kMaskUnlit;
    }
  EXPECT_GT(checked, 101 * 101 / 4);
  EXPECT_GT(shadowed, 20);
}

TEST(Auto, ChoosesZFailWhereTheEyeIsInAVolumeAndZPassWouldBeWrong) {
  const Scene scene = parse_scene_file(scene_path("camera_in_shadow.scene"));
  RenderSettings settings;
  settings.width = settings.height = 120;
  const RenderPlan automatic = make_render_plan(scene, settings);
  EXPECT_EQ(automatic.lights[0].count, DepthCount::kWhereDepthFails);
  EXPECT_EQ(automatic.lights[0].count_reason, "z-fail with caps: the caster at line 9 may shadow the near plane");
  // Forced z-pass is wrong here: the test above would fail with it.
  settings.method = RenderMethod::kZPass;
  const RenderPlan zpass = make_render_plan(scene, settings);
  HeadlessContext context(settings.width, settings.height);
  ShadowRenderer renderer(scene, zpass);
  const test::MaskComparison r = test::compare_with_reference(scene, zpass, renderer.render_mask(0), 0);
  EXPECT_GT(r.unexplained, r.surface_pixels / 4);
}

TEST(Auto, LeavesOutCastersWhoseVolumesCannotReachTheView) {
  // The camera looks down -z at the floor; a sphere behind the camera lit
  // from further behind casts away from the view, one in view does not.
  const Scene scene = parse_scene_text(
      "light 0 0 9\n"
      "triangle -1 -1 -1  1 -1 -1  1 1 -1\n"
      "sphere 0 0 6 0.5\n"
      "sphere 0 0 0 0.3\n",
      "cull.scene");
  RenderSettings settings;
  settings.width = settings.height = 120;
  const RenderPlan automatic = make_render_plan(scene, settings);
  ASSERT_EQ(automatic.lights[0].casters.size(), 3u);
  EXPECT_EQ(automatic.lights[0].culled_casters, 0) << "the sphere at z = 6 shadows the eye's side of the scene";
  EXPECT_EQ(automatic.lights[0].count, DepthCount::kWhereDepthFails) << "the sphere at z = 6 puts the eye in its shadow";
  // Light moved below the floor: the sphere at z = 6 casts upwards, away.
  Scene below = scene;
  below.lights[0].position = {0.0, 0.0, 3.0};
  below.spheres[0].center = {0.0, 0.0, 5.0};
  const RenderPlan culled = make_render_plan(below, settings);
  EXPECT_EQ(culled.lights[0].culled_casters, 1);
  EXPECT_EQ(culled.lights[0].casters[1].volume_phrase, "none: its shadow volume cannot reach the view");
  test::expect_masks_match_reference(below, 120, 120, 64);
}

TEST(ZFail, SphereShadowErrorIsConfinedToTheNgonBand) {
  // With a coarse hexagon the band is wide; every difference
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
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(101, 101, x, y));
      if (!hit || hit->object != 0 || reference_mask_value(scene, 101, 101, x, y, 0) != kMaskUnlit) continue;
      if (reference_mask_value(scene, 101, 101, x - 0.5, y - 0.5, 0) != kMaskUnlit ||
          reference_mask_value(scene, 101, 101, x + 0.5, y + 0.5, 0) != kMaskUnlit)
        continue;  // skip the shadow's edge pixels
      EXPECT_NEAR(image.at(x, y, 0), 0.15 * 255, 1.0) << x << ", " << y;
      ++shadowed;
    }
  EXPECT_GT(shadowed, 20);
}

TEST(Shading, TheRayCastImageHasTheSamePhongValues) {
  const Scene scene = parse_scene_text(
      "light 0 0 2\n"
      "material shiny ambient 1 1 1 diffuse 0.6 0.6 0.6 specular 0.2 0.2 0.2 shininess 1\n"
      "triangle -1 -1 -1  1 -1 -1  1 1 -1 material shiny\n"
      "triangle 0.2 0.2 0  0.6 0.2 0  0.2 0.6 0\n",
      "floor.scene");
  const RayCastFrame frame = ray_cast_frame(scene, 101, 101);
  // Centre: floor point (0, 0, -1) with n = l = v = +z, so r . v = 1:
  // 0.15 ambient + 0.6 diffuse + 0.2 specular = 0.95.
  EXPECT_EQ(frame.image.at(50, 50, 0), 242);  // round(0.95 * 255)
  EXPECT_EQ(frame.masks[0].at(50, 50), kMaskLit);
  // Floor points in the small triangle's shadow: ambient only.
  int shadowed = 0;
  for (int y = 0; y < 101; ++y)
    for (int x = 0; x < 101; ++x) {
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(101, 101, x, y));
      if (!hit || hit->object != 0 || !shadow_ray_blocked(scene, hit->point, 0, scene.lights[0].position)) continue;
      EXPECT_EQ(frame.masks[0].at(x, y), kMaskUnlit);
      EXPECT_EQ(frame.image.at(x, y, 1), 38);  // round(0.15 * 255)
      ++shadowed;
    }
  EXPECT_GT(shadowed, 20);
  EXPECT_EQ(frame.masks[0].at(0, 0), kMaskNoSurface);
  EXPECT_EQ(frame.image.at(0, 0, 2), 0);
}

// The GL image and the ray-cast one, every bundled scene: a channel differs
// by more than one level in 255 (more than rounding) only at a pixel where
// some light's shadow mask differs, which the mask tests explain, or whose
// footprint straddles an edge between surfaces (a corner of it sees another
// object, or none), where the two sample the pixel differently. Measured,
// every such difference is one of those; nothing else differs.
TEST(Shading, TheGLImageMatchesTheRayCastImageWhereMasksAgreeAwayFromEdges) {
  int compared = 0, explained = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(UMBRA_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".scene") continue;
    const Scene scene = parse_scene_file(entry.path().string());
    RenderSettings settings;
    settings.width = settings.height = 120;
    settings.sphere_segments = 256;
    const RenderPlan plan = make_render_plan(scene, settings);
    HeadlessContext context(settings.width, settings.height);
    ShadowRenderer renderer(scene, plan);
    const Image gl = renderer.render_image(false);
    std::vector<Image> masks;
    for (size_t light = 0; light < scene.lights.size(); ++light) masks.push_back(renderer.render_mask(light));
    const RayCastFrame cpu = ray_cast_frame(scene, 120, 120);
    const auto object_at = [&](double x, double y) {
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(120, 120, x, y));
      return hit ? hit->object : -1;
    };
    for (int y = 0; y < 120; ++y)
      for (int x = 0; x < 120; ++x) {
        ++compared;
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(gl.at(x, y, c)) - int(cpu.image.at(x, y, c))));
        if (d <= 1) continue;
        bool mask_differs = false;
        for (size_t light = 0; light < masks.size(); ++light) mask_differs = mask_differs || masks[light].at(x, y) != cpu.masks[light].at(x, y);
        const int object = object_at(x, y);
        bool straddles = false;
        for (const double dx : {-0.5, 0.5})
          for (const double dy : {-0.5, 0.5}) straddles = straddles || object_at(x + dx, y + dy) != object;
        EXPECT_TRUE(mask_differs || straddles) << entry.path().filename() << " pixel (" << x << ", " << y << ") differs by " << d;
        ++explained;
      }
  }
  EXPECT_EQ(compared, 11 * 120 * 120);  // every bundled scene, orthographic.scene included
  EXPECT_LT(explained, compared / 200);  // about 30 pixels in all, measured
}

TEST(Shading, ALightWithNoColourAddsOnlyItsAmbientTerm) {
  // Without the colourless light's pass every surface is its 0.15 ambient,
  // shadow or not, and its mask is still the geometric one.
  const Scene scene = parse_scene_text(
      "light 0 0 2 color 0 0 0\n"
      "triangle -1 -1 -1  1 -1 -1  1 1 -1\n"
      "triangle -1 -1 -1  1 1 -1  -1 1 -1\n"
      "sphere 0 0 0 0.3\n",
      "dark.scene");
  RenderSettings settings;
  settings.width = settings.height = 64;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(64, 64);
  ShadowRenderer renderer(scene, plan);
  const Image image = renderer.render_image(false);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if (reference_mask_value(scene, 64, 64, x, y, 0) != kMaskNoSurface) {
        ASSERT_EQ(image.at(x, y, 0), 38) << x << ", " << y;  // round(0.15 * 255)
      }
  const test::MaskComparison r = test::compare_with_reference(scene, plan, renderer.render_mask(0), 0);
  EXPECT_EQ(r.unexplained, 0);
  EXPECT_TRUE(test::within_boundary_bound(r)) << r.excused_boundary << " excused of " << r.boundary_pixels;
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
