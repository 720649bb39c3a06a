#pragma once
// `--method raycast`: the CPU reference drawn as a whole frame, the shaded
// image with the GL renderer's Phong terms and every light's shadow mask, from
// one eye ray per pixel centre and exact shadow rays (ray_cast.hpp), searched
// through Embree's hierarchy (ray_caster.hpp).

#include <vector>

#include "scene/scene.hpp"
#include "image/image.hpp"

namespace umbra {

struct RayCastFrame {
  Image image;               // RGB (RGBA for a transparent background), as ShadowRenderer::render_image draws it
  std::vector<Image> masks;  // per light, as ShadowRenderer::render_mask draws it
};

// Rows are shared among the machine's cores. With `samples` above 1, the
// image averages samples x samples eye rays per pixel (supersampling, as
// RenderSettings::supersampling draws it); the masks stay one ray, at the
// pixel's centre.
RayCastFrame ray_cast_frame(const Scene& scene, int width, int height, int samples = 1);

}  // namespace umbra
