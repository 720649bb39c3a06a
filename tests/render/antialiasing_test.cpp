// Supersampling (--antialias N): the GL draws the image N times larger and
// averages each N x N block; the ray-cast reference averages N x N eye rays
// at the same points. The two agree away from edges, the masks stay one
// sample at each pixel's centre, and only edge pixels change.
#include <gtest/gtest.h>

#include "reference/ray_cast.hpp"
#include "scene/camera_transform.hpp"
#include "scene/staged_scene.hpp"
#include "tests/render/image_agreement.hpp"

namespace umbra {
namespace {

const std::string kBox = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";

TEST(Antialiasing, TheGlImageMatchesTheReferenceAtEachSampleCount) {
  const Scene scene = parse_scene_or_mesh_file(kBox);
  for (const int samples : {2, 3}) {
    SCOPED_TRACE(samples);
    test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120, RenderMethod::kAuto, samples));
  }
}

TEST(Antialiasing, MasksStayOneSampleAtThePixelCentre) {
  const Scene scene = parse_scene_or_mesh_file(kBox);
  RenderSettings settings;
  settings.width = settings.height = 120;
  const RenderPlan plain = make_render_plan(scene, settings);
  settings.supersampling = 3;
  const RenderPlan smooth = make_render_plan(scene, settings);
  HeadlessContext context(120, 120);
  ShadowRenderer plain_renderer(scene, plain), smooth_renderer(scene, smooth);
  const Image mask = plain_renderer.render_mask(0);
  EXPECT_TRUE(smooth_renderer.render_mask(0).pixels == mask.pixels);
  EXPECT_TRUE(ray_cast_frame(scene, 120, 120, 3).masks[0].pixels == ray_cast_frame(scene, 120, 120, 1).masks[0].pixels);
  // And a supersampled image drawn between two masks is the same image.
  const Image before = smooth_renderer.render_image(false);
  smooth_renderer.render_mask(0);
  EXPECT_TRUE(smooth_renderer.render_image(false).pixels == before.pixels);
}

// On an untextured mesh, a pixel changes by more than a level only where its
// footprint holds an edge: of an object (a corner of it sees another), or of
// a shadow (a neighbour's mask differs). Edges do change: the picture is
// smoother. (On a textured one, the map's own edges change too.)
TEST(Antialiasing, OnlyPixelsOnEdgesChange) {
  const Scene scene = parse_scene_or_mesh_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj");
  const int size = 120;
  const test::RenderedImages one = test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, 1);
  const test::RenderedImages three = test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, 3);
  const Image mask = ray_cast_frame(scene, size, size).masks[0];
  const auto object_at = [&](double x, double y) {
    const auto hit = nearest_hit(scene, scene.camera.eye, pixel_ray_direction(scene.camera, size, size, x, y));
    return hit ? hit->object : -1;
  };
  int changed = 0, unexplained = 0;
  for (int y = 1; y + 1 < size; ++y)
    for (int x = 1; x + 1 < size; ++x) {
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(three.gl.at(x, y, c)) - int(one.gl.at(x, y, c))));
      if (d <= 1) continue;
      ++changed;
      bool edge = false;
      for (const double dx : {-0.5, 0.5})
        for (const double dy : {-0.5, 0.5}) edge = edge || object_at(x + dx, y + dy) != object_at(x, y);
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) edge = edge || mask.at(x + i, y + j) != mask.at(x, y);
      unexplained += !edge;
    }
  EXPECT_EQ(unexplained, 0) << "of " << changed << " pixels changed";
  EXPECT_GT(changed, 100);
}

}  // namespace
}  // namespace umbra
