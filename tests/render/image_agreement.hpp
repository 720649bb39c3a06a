#pragma once
// The GL image against the ray-cast reference's image, pixel by pixel, away
// from the edges of objects and of shadows: wherever a pixel's footprint
// sees one object throughout, lit by the same lights throughout, both must
// draw the same surface in the same colour (to one level in 255; the masks'
// tests hold the shadow edges), except where the point's shadow ray passes through the band
// between a sphere's true shadow cone and its N-gon's (in_ngon_band). A surface clipped away, culled or hidden behind the wrong
// face shows here even where the shadow masks agree.

#include <cstdlib>

#include <gtest/gtest.h>

#include "scene/camera.hpp"
#include "tests/render/mask_comparison.hpp"
#include "reference/ray_cast.hpp"
#include "reference/ray_cast_render.hpp"
#include "render/headless_context.hpp"
#include "render/shadow_renderer.hpp"

namespace umbra::test {

struct RenderedImages {
  Image gl, cpu;
};

inline RenderedImages render_gl_and_ray_cast(const Scene& scene, int size, RenderMethod method = RenderMethod::kAuto,
                                             int supersampling = 1) {
  RenderSettings settings;
  settings.method = method;
  settings.width = settings.height = size;
  settings.antialias = supersampling;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(settings.width, settings.height);
  ShadowRenderer renderer(scene, plan);
  return {renderer.render_image(false), ray_cast_frame(scene, size, size, supersampling).image};
}

// How many channels (alpha too, where there is one) of pixels that see one
// object throughout differ by more than one level.
inline int differing_channels_away_from_edges(const Scene& scene, const RenderedImages& r,
                                              int segments = RenderSettings{}.sphere_segments) {
  const int w = r.gl.width, h = r.gl.height;
  const auto object_at = [&](double x, double y) {
    const auto hit = nearest_hit(scene, scene.camera.pixel_ray(w, h, x, y));
    return hit ? hit->object : -1;
  };
  const auto in_a_band = [&](int x, int y) {
    const auto hit = nearest_hit(scene, scene.camera.pixel_ray(w, h, x, y));
    for (const Light& light : scene.lights)
      for (const Sphere& sphere : scene.spheres)
        if (hit && in_ngon_band(sphere, light.position, hit->point, segments)) return true;
    return false;
  };
  int differing = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int object = object_at(x, y);
      bool straddles = false;
      for (const double dx : {-0.5, 0.5})
        for (const double dy : {-0.5, 0.5}) {
          straddles = straddles || object_at(x + dx, y + dy) != object;
          for (size_t light = 0; light < scene.lights.size() && !straddles; ++light)
            straddles = reference_mask_value(scene, w, h, x + dx, y + dy, light) != reference_mask_value(scene, w, h, x, y, light);
        }
      if (straddles || in_a_band(x, y)) continue;
      for (int c = 0; c < r.gl.channels; ++c) differing += std::abs(int(r.gl.at(x, y, c)) - int(r.cpu.at(x, y, c))) > 1;
    }
  return differing;
}

inline void expect_images_agree(const Scene& scene, const RenderedImages& r) {
  EXPECT_EQ(differing_channels_away_from_edges(scene, r), 0) << scene.path;
}

}  // namespace umbra::test
