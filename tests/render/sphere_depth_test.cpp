// A sphere's depth is the exact ray-sphere hit of the ray through each
// pixel's centre, as the ray-cast reference traces it. Near a sphere's
// outline the hit moves fast with the ray (the depth goes as the square
// root of the distance to the outline), so a ray a few hundredths of a pixel
// off puts the surface behind a shadow volume's face that lies just behind it.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "reference/ray_cast.hpp"
#include "render/headless_context.hpp"
#include "render/render_plan.hpp"
#include "render/shadow_renderer.hpp"
#include "scene/camera.hpp"
#include "scene/scene_parser.hpp"

namespace umbra {
namespace {

// gl_FragDepth is computed in float, whose steps near depth 1 are the 24-bit
// buffer's own: a few steps of rounding, where a ray aimed at an
// interpolated position put an H100's depth 54 steps off near an outline.
constexpr double kDepthStepsOfRounding = 4.0;

struct DepthAgreement {
  int sphere_pixels = 0;
  int beyond_rounding = 0;
  double worst_steps = 0.0;  // in steps of the 24-bit depth buffer
  std::string worst_pixel;
};

DepthAgreement compare_sphere_depths(const Scene& scene, int width, int height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(width, height);
  ShadowRenderer renderer(scene, plan);
  renderer.render_image(false);
  const std::vector<float> depth = renderer.read_depth();
  const glm::dmat4 view_projection =
      plan.camera.view_projection(double(width) / height, plan.near_plane);
  DepthAgreement r;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const auto hit = nearest_hit(scene, plan.camera.pixel_ray(width, height, x, y));
      if (!hit || hit->object >= int(scene.spheres.size())) continue;
      const float gl = depth[size_t(height - 1 - y) * size_t(width) + size_t(x)];
      if (gl >= 1.0f) continue;
      ++r.sphere_pixels;
      const glm::dvec4 clip = view_projection * glm::dvec4(hit->point, 1.0);
      const double exact = 0.5 * clip.z / clip.w + 0.5;
      const double steps = std::abs(double(gl) - exact) * double(1 << 24);
      r.beyond_rounding += steps > kDepthStepsOfRounding;
      if (steps > r.worst_steps) {
        std::ostringstream s;
        s << "pixel (" << x << ", " << y << ")";
        r.worst_steps = steps, r.worst_pixel = s.str();
      }
    }
  return r;
}

TEST(SphereDepth, IsTheExactHitOfThePixelCentresRay) {
  const Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/many_spheres.scene");
  const DepthAgreement r = compare_sphere_depths(scene, 160, 120);
  EXPECT_GT(r.sphere_pixels, 1000);
  EXPECT_EQ(r.beyond_rounding, 0) << "of " << r.sphere_pixels << " sphere pixels; the worst, " << r.worst_pixel
                                  << ", by " << r.worst_steps << " steps of the depth buffer";
}

// ShadowRenderer::view_depth: at each pixel, the distance along the view
// axis to the surface the pixel's centre ray hits first, +infinity where it
// hits none; also after a frame drawn with 3 x 3 samples, which it draws again
// at one.
TEST(ViewDepth, IsTheExactHitsDistanceAlongTheViewAxis) {
  const Scene scene = parse_scene_text("light 0.3 0.2 3\n"
                                       "camera eye 0 0 5 target 0 0 0 up 0 1 0 fovy 30\n"
                                       "triangle -1 -1 0  1 -1 0  1 1 0\n"
                                       "triangle -1 -1 0  1 1 0  -1 1 0\n"
                                       "sphere 0.3 0.4 0.6 0.25\n",  // off centre: a picture turned over would show
                                       "depth.scene");
  for (const int samples : {1, 3}) {
    RenderSettings settings;
    settings.width = 81, settings.height = 61;
    settings.antialias = samples;
    const RenderPlan plan = make_render_plan(scene, settings);
    HeadlessContext context(settings.width, settings.height);
    ShadowRenderer renderer(scene, plan);
    renderer.render_image(false);
    const std::vector<float> depth = renderer.view_depth();
    ASSERT_EQ(depth.size(), size_t(81 * 61));
    const glm::dvec3 forward = glm::normalize(scene.camera.target - scene.camera.eye);
    int surfaces = 0, background = 0, off = 0;
    for (int y = 0; y < 61; ++y)
      for (int x = 0; x < 81; ++x) {
        const float seen = depth[size_t(y) * 81 + size_t(x)];
        const auto hit = nearest_hit(scene, scene.camera.pixel_ray(81, 61, x, y));
        if (!hit) {
          background += std::isinf(seen) != 0;
          off += std::isinf(seen) == 0;
          continue;
        }
        const double exact = glm::dot(hit->point - scene.camera.eye, forward);
        ++surfaces;
        off += !(std::abs(seen - exact) < 1e-3 * exact);  // the 24-bit buffer's steps, far from the near plane
      }
    EXPECT_GT(surfaces, 1000) << samples;
    EXPECT_GT(background, 100) << samples;
    EXPECT_EQ(off, 0) << "pixels whose depth is not the exact hit's, at " << samples << " x " << samples << " samples";
  }
}

}  // namespace
}  // namespace umbra
