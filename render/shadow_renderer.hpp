#pragma once
// Draws a scene with exact hard shadows into a float framebuffer of its own
// (FrameTarget), which a window then shows:
//   1. depth + ambient for every surface;
//   2. per light with colour: its shadow technique casts the light's shadows
//      (stencil volumes, a cube shadow map, or planar projections; see
//      shadow_technique.hpp), then the light's diffuse and specular terms are
//      added where the technique says the surface is lit.

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "image/image.hpp"
#include "scene/scene.hpp"
#include "render/draw_pacing.hpp"
#include "render/render_plan.hpp"

namespace umbra {

class FrameDrawing;
class ShadowTechnique;

class ShadowRenderer {
 public:
  // Requires a current GL 3.3 core context that can draw
  // plan.settings.width x height pixels. Reads `plan` when it draws, so a
  // viewer may change it between frames. `sending`: kPaced for a picture,
  // kWhole for a run of frames (draw_pacing.hpp).
  ShadowRenderer(const Scene& scene, const RenderPlan& plan, DrawSending sending = DrawSending::kPaced);
  ~ShadowRenderer();

  // Draws the frame into its own framebuffer, which stays bound, so that a
  // viewer's overlay can be drawn over it. With show_volumes, every
  // light's volumes are drawn over it translucently, front faces only (the
  // debugging view). The plan's camera, size and method are read each time.
  // `while_first_pass_draws`, if given, runs once the first pass (depth and
  // ambient light, which reads no light's volumes) is sent, before any
  // light's: it may update the plan's lights, but not its camera or size.
  void draw(bool show_volumes, const std::function<void()>& while_first_pass_draws = nullptr);
  // Draws the frame into framebuffer `into` (0: the default one, a window)
  // as the picture read back from it would be: the mean of each pixel's
  // samples, toned by the scene's curve, rounded there. Leaves `into`
  // bound, for an overlay; the next draw binds the frame again.
  void show(unsigned into = 0) const;
  // What show draws, read back from an 8-bit framebuffer of the frame's
  // size (as a window holds it): how a headless test sees the window.
  Image read_shown() const;
  // Waits until the GL has finished every command so far (for timing).
  void finish() const;
  // The shaded image (RGB, or RGBA where the scene's background is
  // transparent): draw, then read it back.
  Image render_image(bool show_volumes);
  // What the last draw left in the framebuffer (as render_image).
  Image read_image() const;
  // The window depth the last draw left, per pixel, rows from the bottom; 1
  // where no surface was drawn. For one sample a pixel (--antialias 1).
  std::vector<float> read_depth() const;
  // The depth of the surface seen at each pixel's centre, as its distance
  // along the camera's view axis in scene units (to the 24-bit depth
  // buffer's precision), rows from the top; +infinity where no surface is.
  // Draws the depth again at one sample a pixel where the last frame took more.
  std::vector<float> view_depth();

  // Light `light`'s shadow mask (grey): kMaskNoSurface where no surface is
  // seen, kMaskLit where the visible point faces the light and is outside its
  // shadow, kMaskUnlit elsewhere.
  Image render_mask(size_t light);
  // The shaded image and light `light`'s mask, as render_image and then
  // render_mask make them. At one sample a pixel, where that light was the
  // last the image cast and its technique's cast outlives the direct pass,
  // the mask is drawn over the image's depth and cast rather than anew.
  std::pair<Image, Image> render_image_and_mask(bool show_volumes, size_t light);

 private:
  ShadowTechnique& technique();  // the plan's method's, made anew when the method changes
  void depth_and_ambient_pass(int samples);  // per side
  void direct_light_pass(size_t light);
  void show_volumes_pass();
  void mask_passes(size_t light);
  Image read_mask() const;  // after mask_passes
  glm::vec3 nothing_seen() const;  // a sample that sees no surface (pixel_mean.hpp), as the window shows it

  const RenderPlan& plan_;
  std::unique_ptr<FrameDrawing> drawing_;
  std::unique_ptr<ShadowTechnique> technique_;
  RenderMethod technique_method_ = RenderMethod::kAuto;
  std::optional<size_t> last_cast_light_;  // over the depth now in the framebuffer
};

}  // namespace umbra
