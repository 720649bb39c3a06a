// The background: a colour where no surface is seen, or transparent (alpha 0
// there, in an RGBA picture), drawn by the GL as the ray-cast reference
// draws it, with and without supersampling.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "scene/camera.hpp"
#include "scene/scene_parser.hpp"
#include "tests/render/image_agreement.hpp"

namespace umbra {
namespace {

// Two spheres over a floor that leaves the frame's top uncovered.
Scene spheres_with(const std::string& background) {
  return parse_scene_text("light 0.6 0.8 1.6\nmaterial red diffuse 0.9 0.2 0.2\n"
                          "triangle -1 -1 -1  1 -1 -1  1 1 -1\ntriangle -1 -1 -1  1 1 -1  -1 1 -1\n"
                          "sphere 0 0 -0.3 0.35 material red\nsphere 0.5 0.4 0.2 0.15\n"
                          "camera eye 0 -2.5 1.2 target 0 0 -0.4 up 0 0 1 fovy 50\n" + background,
                          "background.scene");
}

// Whether the reference's rays through the pixel's centre and corners all
// see a surface (1), all see nothing (0), or some do (-1).
int coverage(const Scene& scene, int size, int x, int y) {
  int seen = 0;
  for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, {-0.5, -0.5}, {0.5, -0.5}, {-0.5, 0.5}, {0.5, 0.5}})
    seen += nearest_hit(scene, scene.camera.pixel_ray(size, size, x + dx, y + dy)).has_value();
  return seen == 5 ? 1 : seen == 0 ? 0 : -1;
}

TEST(Background, TransparentIsAlphaZeroExactlyWhereTheReferenceSeesNothing) {
  const Scene scene = spheres_with("background transparent\n");
  const int size = 100;
  for (const int samples : {1, 3}) {
    SCOPED_TRACE(samples);
    const test::RenderedImages r = test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, samples);
    ASSERT_EQ(r.gl.channels, 4);
    ASSERT_EQ(r.cpu.channels, 4);
    int empty = 0, full = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const int covered = coverage(scene, size, x, y);
        if (covered == 0) {
          ++empty;
          EXPECT_EQ(r.gl.at(x, y, 3), 0) << x << ", " << y;
          EXPECT_EQ(r.cpu.at(x, y, 3), 0) << x << ", " << y;
        } else if (covered == 1) {
          ++full;
          EXPECT_EQ(r.gl.at(x, y, 3), 255) << x << ", " << y;
          EXPECT_EQ(r.cpu.at(x, y, 3), 255) << x << ", " << y;
        } else {  // an edge: the coverage the samples saw, alike to a level
          EXPECT_LE(std::abs(int(r.gl.at(x, y, 3)) - int(r.cpu.at(x, y, 3))), 1) << x << ", " << y;
        }
      }
    EXPECT_GT(empty, size * size / 10) << "the scene should leave part of the frame empty";
    EXPECT_GT(full, size * size / 4);
    test::expect_images_agree(scene, r);
  }
}

TEST(Background, AColourFillsWhatNoSurfaceCoversAndBlendsAtEdges) {
  const Scene scene = spheres_with("background 0.2 0.4 0.6\n");
  const int size = 100;
  for (const int samples : {1, 3}) {
    SCOPED_TRACE(samples);
    const test::RenderedImages r = test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, samples);
    ASSERT_EQ(r.gl.channels, 3);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        if (coverage(scene, size, x, y) != 0) continue;
        for (int c = 0; c < 3; ++c) EXPECT_EQ(r.gl.at(x, y, c), channel_byte(0.2 * (c + 1))) << x << ", " << y;
      }
    test::expect_images_agree(scene, r);
  }
}

// A shadow catcher is unseen but for its shadow: over a transparent
// background, the floor's alpha is above 0 exactly where its mask says
// unlit, the share of light the shadow takes, and 0 where it is lit; the GL
// draws it as the ray-cast reference does, at one sample and at three.
TEST(Background, AShadowCatchersAlphaIsItsShadow) {
  const Scene scene = parse_scene_text("light 0.6 0.8 1.6 ambient 0.3 0.3 0.3\nmaterial catch shadow-catcher\n"
                                       "floor -1 size 3 material catch\nsphere 0 0 -0.3 0.35\nsphere 0.5 0.4 0.2 0.15\n"
                                       "camera eye 0 -2.5 1.2 target 0 0 -0.4 up 0 0 1 fovy 50\nbackground transparent\n",
                                       "catcher.scene");
  const int size = 100;
  RenderSettings settings;
  settings.width = settings.height = size;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(size, size);
  ShadowRenderer renderer(scene, plan);
  const Image mask = renderer.render_mask(0);
  const Image image = renderer.render_image(false);
  int shadowed = 0, lit = 0;
  // The share a shadow takes from the floor: the light's term over all of it.
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(size, size, x, y));
      if (!hit || hit->object != 2 || coverage(scene, size, x, y) != 1) continue;  // the floor's own pixels
      if (mask.at(x, y) == kMaskUnlit) {
        ++shadowed;
        const glm::dvec3 l = glm::normalize(scene.lights[0].position - hit->point);
        const double direct = l.z;  // the floor's normal is +z, the light white
        EXPECT_NEAR(image.at(x, y, 3), 255.0 * direct / (0.3 + direct), 1.0) << x << ", " << y;
        EXPECT_EQ(image.at(x, y, 0), 0);  // black: a shadow
      } else if (mask.at(x, y) == kMaskLit) {
        ++lit;
        EXPECT_EQ(image.at(x, y, 3), 0) << x << ", " << y;
      }
    }
  EXPECT_GT(shadowed, 100);
  EXPECT_GT(lit, 1000);
  for (const int samples : {1, 3}) {
    SCOPED_TRACE(samples);
    test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, samples));
  }
}

}  // namespace
}  // namespace umbra
