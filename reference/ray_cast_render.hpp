#pragma once
// `--method raycast`: the CPU reference drawn as a whole frame, the shaded
// image with the GL renderer's Phong terms and every light's shadow mask, from
// one eye ray per pixel centre and exact shadow rays (ray_cast.hpp), searched
// through Embree's hierarchy (ray_caster.hpp).

#include <vector>

#include "scene/scene.hpp"
#include "image/edge_pixels.hpp"
#include "image/image.hpp"

namespace umbra {

struct RayCastFrame {
  Image image;               // RGB (RGBA for a transparent background), as ShadowRenderer::render_image draws it
  std::vector<Image> masks;  // per light, as ShadowRenderer::render_mask draws it
};

class RayCaster;

// Rows are shared among the machine's cores. With `samples` above 1, the
// image averages samples x samples eye rays per pixel, at every pixel (as
// RenderSettings::supersampling draws it) or at those the one-sample frame
// shows an edge at (ray_cast_edge_pixels); the masks stay one ray, at the
// pixel's centre.
RayCastFrame ray_cast_frame(const Scene& scene, int width, int height, int samples = 1,
                            AntialiasedPixels where = AntialiasedPixels::kAll);

// Antialiasing at edges: `image` is `scene`'s picture drawn with one sample
// a pixel, at its centre (by the GL or by rays). Each pixel edge_pixels
// finds on an edge is drawn again from samples x samples exact eye rays
// through `caster` (built over `scene`), averaged, as a frame supersampled
// everywhere would draw it; the rest are kept. Returns how many were drawn.
size_t ray_cast_edge_pixels(const Scene& scene, const RayCaster& caster, Image& image, int samples);

}  // namespace umbra
