// What umbra view's window shows of a frame (ShadowRenderer::show) is the
// picture read back from it: each pixel the mean of its samples, toned by
// the scene's curve (a staged model's soft shoulder), to within the one
// level that the GL's float mean and rounding may differ by from the
// picture's double.
#include <cstdlib>

#include <gtest/gtest.h>

#include "render/headless_context.hpp"
#include "render/render_plan.hpp"
#include "render/shadow_renderer.hpp"
#include "scene/staged_scene.hpp"

namespace umbra {
namespace {

int largest_difference(const Image& a, const Image& b) {
  int most = 0;
  for (size_t k = 0; k < a.pixels.size(); ++k) most = std::max(most, std::abs(int(a.pixels[k]) - int(b.pixels[k])));
  return most;
}

TEST(ShownFrame, TheWindowShowsThePictureTonedAtEachSampleCount) {
  Scene scene = parse_scene_or_mesh_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj");
  ASSERT_EQ(scene.tone, ToneCurve::kSoft);
  // A key light bright enough that its highlights pass the curve's knee.
  scene.lights.at(0).color = glm::dvec3(1.5);
  const int size = 96;
  for (const int samples : {1, 3}) {
    SCOPED_TRACE(samples);
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.antialias = samples;
    const RenderPlan plan = make_render_plan(scene, settings);
    HeadlessContext context(size, size);
    ShadowRenderer renderer(scene, plan);
    const Image picture = renderer.render_image(false);
    EXPECT_LE(largest_difference(renderer.read_shown(), picture), 1);
    // The curve matters here: the same frame clipped, not toned, is further off.
    Scene clipped = scene;
    clipped.tone = ToneCurve::kClip;
    ShadowRenderer clipping(clipped, plan);
    EXPECT_GT(largest_difference(clipping.render_image(false), picture), 4);
  }
}

}  // namespace
}  // namespace umbra
