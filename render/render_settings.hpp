#pragma once
// What a frame is asked to be, as plain values: its size, its method and
// the method's parameters, and its samples. The render plan is made for
// them (render_plan.hpp); the command line fills them in.

#include "image/edge_pixels.hpp"
#include "render/render_method.hpp"

namespace umbra {

struct RenderSettings {
  int width = 800;
  int height = 800;
  int sphere_segments = 64;  // N of the tangent circle's inscribed N-gon (docs/geometry.md)
  RenderMethod method = RenderMethod::kAuto;  // the plan is for every method but kRaycast
  int shadow_map_size = 1024;                 // texels along a cube face's side, for kShadowMap
  // The image's samples per pixel along each side (--antialias N, the
  // scene's antialias statement), averaged (box-filtered) then rounded, at
  // the pixels `antialiased` says. kAll: the frame is drawn that many times
  // larger (supersampling). kEdges: the GL draws one sample a pixel, and
  // whoever asked for the picture draws its edge pixels again from exact
  // rays (ray_cast_edge_pixels). Masks are always one sample, at the
  // pixel's centre.
  int antialias = 1;
  AntialiasedPixels antialiased = AntialiasedPixels::kAll;

  // Samples per side the GL's frame is drawn with.
  int frame_samples() const { return antialiased == AntialiasedPixels::kAll ? antialias : 1; }

  // Every setting, as declared: one added joins it, so a plan made for its old value is never kept.
  bool operator==(const RenderSettings&) const = default;
};

}  // namespace umbra
