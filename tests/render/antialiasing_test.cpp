// Supersampling (--antialias N): the GL draws the image N times larger and
// averages each N x N block; the ray-cast reference averages N x N eye rays
// at the same points. The two agree away from edges, the masks stay one
// sample at each pixel's centre, and only edge pixels change.
#include <iostream>

#include <gtest/gtest.h>

#include "image/edge_pixels.hpp"
#include "reference/ray_cast.hpp"
#include "reference/ray_caster.hpp"
#include "scene/camera.hpp"
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
  settings.antialias = 3;
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
    const auto hit = nearest_hit(scene, scene.camera.pixel_ray(size, size, x, y));
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

// Antialiasing at edges (the default for a staged mesh): the GL's one-sample
// picture, with each pixel edge_pixels finds drawn again from N x N exact
// rays, is the ray-cast frame supersampled everywhere at those pixels and
// the GL's one sample elsewhere; and supersampling everywhere changes no
// pixel it leaves (by more than the GL's rounding), so it misses no edge.
TEST(Antialiasing, AtEdgesThePixelsThatSupersamplingChangesAreDrawnFromRays) {
  for (const std::string& path : {std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj", kBox}) {
    SCOPED_TRACE(path);
    const Scene scene = parse_scene_or_mesh_file(path);
    const int size = 100;
    const test::RenderedImages one = test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, 1);
    const test::RenderedImages three = test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, 3);
    Image edges = one.gl;
    const size_t drawn = ray_cast_edge_pixels(scene, RayCaster(scene), edges, 3);
    const std::vector<uint8_t> edge = edge_pixels(one.gl);
    int marked = 0, missed = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const bool on_edge = edge[size_t(y) * size + size_t(x)];
        marked += on_edge;
        int changed = 0;
        for (int c = 0; c < 3; ++c) {
          ASSERT_EQ(edges.at(x, y, c), on_edge ? three.cpu.at(x, y, c) : one.gl.at(x, y, c)) << x << " " << y;
          changed = std::max(changed, std::abs(int(three.gl.at(x, y, c)) - int(one.gl.at(x, y, c))));
        }
        missed += !on_edge && changed > 1;
      }
    EXPECT_EQ(size_t(marked), drawn);
    EXPECT_GT(marked, 200);
    EXPECT_EQ(missed, 0) << "pixels supersampling changes that no edge marks";
  }
}

// The mean error at edges, against a 16 x 16 reference (4 x 4 rays at 4
// times the size, box-filtered down): edge pixels drawn from 3 x 3 rays come
// as close as the GL's frame supersampled 3 x 3 everywhere (to a hundredth
// of a level: the rays and the GL's rasteriser put the same samples on
// slightly different sides of a mesh's edges), and 4 x 4 closer.
TEST(Antialiasing, AtEdgesThePictureIsAsCloseToAFineReferenceAsSupersampledEverywhere) {
  const Scene scene = parse_scene_or_mesh_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj");
  const int size = 64, factor = 4;
  const Image fine = ray_cast_frame(scene, size * factor, size * factor, 4).image;
  const auto mean_edge_error = [&](const Image& picture) {
    double sum = 0.0;
    int edges = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        double error = 0.0;
        bool edge = false;
        for (int c = 0; c < 3; ++c) {
          int lo = 255, hi = 0, total = 0;
          for (int j = 0; j < factor; ++j)
            for (int i = 0; i < factor; ++i) {
              const int v = fine.at(x * factor + i, y * factor + j, c);
              lo = std::min(lo, v), hi = std::max(hi, v), total += v;
            }
          edge = edge || hi - lo > 2;
          error = std::max(error, std::abs(picture.at(x, y, c) - total / double(factor * factor)));
        }
        if (edge) sum += error, ++edges;
      }
    return sum / edges;
  };
  const RayCaster caster(scene);
  const Image one = test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, 1).gl;
  Image three = one, four = one;
  ray_cast_edge_pixels(scene, caster, three, 3);
  ray_cast_edge_pixels(scene, caster, four, 4);
  const double everywhere = mean_edge_error(test::render_gl_and_ray_cast(scene, size, RenderMethod::kAuto, 3).gl);
  const double single = mean_edge_error(one);
  EXPECT_NEAR(mean_edge_error(three), everywhere, 0.01);
  EXPECT_LT(mean_edge_error(four), everywhere);
  EXPECT_LT(everywhere, single / 2.0);
  std::cout << "mean error at edges: one sample " << single << ", 3 x 3 everywhere " << everywhere << ", 3 x 3 at edges "
            << mean_edge_error(three) << ", 4 x 4 at edges " << mean_edge_error(four) << "\n";
}

}  // namespace
}  // namespace umbra
